//! Integration tests: one binary (`autotests = false`), modules per topic.

mod api;
mod batch;
mod cli;
mod earcut;
mod errors;
mod formats;
mod geo;
mod gis;
mod holes_dp;
mod hostile;
mod pipelines;
mod property;
mod pseudo;
mod svg;
mod touching;
mod util;
mod wide;
