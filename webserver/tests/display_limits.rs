//! The operator display keeps answering when many pages hold its event stream open (or sit idle on
//! it): more than the server's 64 connections of `GET /events` do not keep a new page out — the
//! longest-open stream is closed to make room, and its page's EventSource reconnects by itself.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

/// Sends `GET path` with the display's own Host and returns the response's first line.
fn request(bound: std::net::SocketAddr, path: &str, close: bool) -> (TcpStream, String) {
    let mut s = TcpStream::connect(bound).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    let connection = if close { "Connection: close\r\n" } else { "" };
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {bound}\r\n{connection}\r\n"
    )
    .unwrap();
    let mut head = Vec::new();
    let mut byte = [0_u8; 1];
    while !head.ends_with(b"\r\n") {
        match s.read(&mut byte) {
            Ok(1) => head.push(byte[0]),
            _ => break,
        }
    }
    (s, String::from_utf8_lossy(&head).trim().to_owned())
}

#[test]
fn the_operator_display_keeps_answering_under_many_open_event_streams() {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    let (listener, bound) = ergocell_web::display::bind("127.0.0.1:0".parse().unwrap()).unwrap();
    let display = ergocell_web::display::Display::new();
    let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
    let server = runtime.spawn(ergocell_web::display::serve(listener, display, async {
        let _ = stopped.await;
    }));
    // 80 pages on the event stream, more than the 64 connections the server holds at a time.
    let mut pages = Vec::new();
    for k in 0..80 {
        let (s, status) = request(bound, "/events", false);
        assert_eq!(status, "HTTP/1.1 200 OK", "event stream {k}");
        pages.push(s);
    }
    // A new page still loads, and a new event stream still opens.
    let (_s, status) = request(bound, "/", true);
    assert_eq!(status, "HTTP/1.1 200 OK");
    let (_s, status) = request(bound, "/events", false);
    assert_eq!(status, "HTTP/1.1 200 OK");
    // The oldest streams were closed to make room (their pages reconnect by themselves).
    let closed = pages
        .iter_mut()
        .map(|s| {
            s.set_read_timeout(Some(Duration::from_millis(200)))
                .unwrap();
            let mut buf = [0_u8; 4096];
            loop {
                match s.read(&mut buf) {
                    Ok(0) => return true,
                    Ok(_) => {}
                    Err(_) => return false,
                }
            }
        })
        .filter(|closed| *closed)
        .count();
    assert!(closed >= 16, "{closed} of 80 streams closed");
    let _ = stop.send(());
    runtime.block_on(server).unwrap().unwrap();
}
