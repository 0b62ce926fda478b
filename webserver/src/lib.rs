//! The cell's two local web servers, on one HTTP stack with one set of limits:
//! - [`review_server`]: the offline review (`ergocell review`): a recording's pages, served to the
//!   ergonomist's browser; the accept loop (connection cap, header read timeout, graceful stop), the
//!   Host and method rules, and the limits both servers share;
//! - [`display`]: the operator display (`ergocell run` and `demo` with `--display`): the session's
//!   current picture pushed to the cell's screen as server-sent events.
//!
//! What it owns: HTTP (axum on hyper, HTTP/1 only), routing, the Host rules against DNS rebinding,
//! the connection limits, and folding the session's events into the display's picture. What it must
//! not do: decide anything about the session or the robot (it only shows what the cell did), read
//! or write files (the pages come rendered from `ergocell_review`, the display's page is built in),
//! or speak ROS. The binary starts them from its commands: it binds the review's listener, the
//! display binds its own ([`display::bind`]).

pub mod display;
pub mod review_server;
