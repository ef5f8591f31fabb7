//! grafika: a step-by-step tutor and calculator for the 3D viewing pipeline
//! and shading of the course text.
//!
//! Data flows one way: command-line flags or a problem file are validated
//! into plain values, the stage functions (camera → projection → window →
//! clip) compute with them at the chosen precision while writing their
//! steps to a [`trace::Trace`], and a [`report::Report`] turns the steps and
//! results into text or JSON.

pub mod accuracy;
pub mod bench;
pub mod camera;
pub mod check;
pub mod check_cmd;
pub mod cli;
pub mod clip;
pub mod commands;
pub mod diagnose;
pub mod error;
pub mod generate;
pub mod input;
pub mod lighting;
pub mod lighting_input;
pub mod mesh;
pub mod num;
pub mod problem;
pub mod projection;
pub mod raster;
pub mod render;
pub mod render_cmd;
pub mod report;
pub mod report_doc;
pub mod rng;
pub mod scene;
pub mod solve;
pub mod trace;
pub mod vec;
pub mod window;
