//! Integration tests: one binary (`autotests = false`), modules per topic.

mod cli;
mod holes_dp;
mod property;
mod util;
