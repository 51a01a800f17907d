//! Integration tests: one binary (`autotests = false`), modules per topic.

mod batch;
mod cli;
mod earcut;
mod errors;
mod formats;
mod geo;
mod holes_dp;
mod property;
mod pseudo;
mod svg;
mod util;
mod wide;
