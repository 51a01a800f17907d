//! Integration tests: one binary (`autotests = false`), modules per topic.

mod cli;
mod property;
mod util;
