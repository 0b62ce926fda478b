//! Issue row "review server: connections that never finish their headers stay open forever (246 idle
//! sockets starve it at `ulimit -n 128`); Ctrl-C does not stop it during a half-sent request".
//!
//! `ergocell review` on loopback, against clients that hold connections without finishing a request:
//! it keeps answering (at most 64 connections, the longest idle closed to make room), closes a
//! connection whose request head does not arrive within the header timeout (also the idle keep-alive
//! timeout) and one that stopped reading its response (stall timeout), and SIGTERM or Ctrl-C stop it
//! at once with exit 0 even while a request is half sent. The timeouts are shortened for the tests
//! through hidden flags (`--header-timeout-ms`, `--stall-timeout-ms`).

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufReader, ErrorKind, Lines, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdout, Command, ExitStatus};
use std::time::{Duration, Instant};

mod common;

/// Wall-clock instant: these tests time a real server's timeouts and exit (no injected clock).
#[allow(clippy::disallowed_methods)]
fn now() -> Instant {
    Instant::now()
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// One short demo session, recorded once for all tests of this file.
fn demo_recording() -> &'static Path {
    common::demo_recording("review-limits-demo.mcap")
}

/// A running `ergocell review <demo> --port 0 <extra>`, killed on drop.
struct Server {
    child: Child,
    /// `127.0.0.1:<port>`, the Host the server answers.
    authority: String,
    /// The rest of its stdout, read after it exited.
    lines: Lines<BufReader<ChildStdout>>,
}

impl Server {
    /// Starts the server, at `ulimit -n <fd_limit>` if given (through `sh`, which `exec`s it: the
    /// child's pid is the server's), and waits for its URL.
    fn start(extra: &[&str], fd_limit: Option<u32>) -> Self {
        let rec = demo_recording();
        let command = match fd_limit {
            Some(n) => {
                let mut c = Command::new("sh");
                c.arg("-c")
                    .arg(format!("ulimit -n {n} && exec \"$0\" \"$@\""))
                    .arg(env!("CARGO_BIN_EXE_ergocell"));
                c
            }
            None => Command::new(env!("CARGO_BIN_EXE_ergocell")),
        };
        let (child, url, lines) = common::spawn_review(command, &root(), rec, extra);
        let authority = url
            .trim_start_matches("http://")
            .trim_end_matches('/')
            .to_owned();
        assert!(authority.starts_with("127.0.0.1:"), "{url}");
        Self {
            child,
            authority,
            lines,
        }
    }

    fn connect(&self) -> TcpStream {
        let addr = self.authority.parse().unwrap();
        let s = TcpStream::connect_timeout(&addr, Duration::from_secs(5))
            .unwrap_or_else(|e| panic!("connect to {addr}: {e}"));
        s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        s.set_write_timeout(Some(Duration::from_secs(5))).unwrap();
        s
    }

    /// `GET <target>` on a new connection (`Connection: close`): the status and how long it took.
    fn get(&self, target: &str) -> (u16, Duration) {
        let started = now();
        let mut s = self.connect();
        write!(
            s,
            "GET {target} HTTP/1.1\r\nHost: {}\r\nConnection: close\r\n\r\n",
            self.authority
        )
        .unwrap();
        let mut buf = Vec::new();
        if let Err(e) = s.read_to_end(&mut buf) {
            panic!("GET {target}: {e} after {} bytes", buf.len());
        }
        let status = String::from_utf8_lossy(&buf)
            .split_whitespace()
            .nth(1)
            .and_then(|c| c.parse().ok())
            .unwrap_or(0);
        (status, started.elapsed())
    }

    /// Sends `signal` (`TERM`, `INT`) with `kill`, waits at most `limit` for the exit: its status and
    /// the time it took.
    fn kill_and_wait(&mut self, signal: &str, limit: Duration) -> (ExitStatus, Duration) {
        let sent = now();
        let kill = Command::new("kill")
            .arg(format!("-{signal}"))
            .arg(self.child.id().to_string())
            .status()
            .unwrap();
        assert!(kill.success(), "kill -{signal}");
        while sent.elapsed() < limit {
            if let Some(status) = self.child.try_wait().unwrap() {
                return (status, sent.elapsed());
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        panic!("still running {limit:?} after SIGTERM/SIGINT ({signal})");
    }

    /// What it printed after its URL (read once it exited).
    fn rest_of_output(&mut self) -> String {
        self.lines
            .by_ref()
            .map_while(Result::ok)
            .collect::<Vec<_>>()
            .join("\n")
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// How a connection ends: closed by the server (EOF or reset) or still open when the read timed out.
fn closed_by_server(s: &mut TcpStream) -> bool {
    let mut buf = [0_u8; 4096];
    loop {
        match s.read(&mut buf) {
            Ok(0) => return true,
            Ok(_) => {}
            Err(e) if e.kind() == ErrorKind::ConnectionReset => return true,
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {
                return false
            }
            Err(e) => panic!("read: {e}"),
        }
    }
}

/// Waits (at most `limit`) for the server to close `s`; how long that took.
fn time_to_close(s: &mut TcpStream, limit: Duration) -> Option<Duration> {
    let started = now();
    s.set_read_timeout(Some(limit)).unwrap();
    closed_by_server(s).then(|| started.elapsed())
}

/// Opens `n` connections that each send half a request line and nothing else.
fn half_sent_requests(server: &Server, n: usize) -> Vec<TcpStream> {
    (0..n)
        .map(|_| {
            let mut s = server.connect();
            s.write_all(b"GET / HT").unwrap();
            s
        })
        .collect()
}

#[test]
fn connections_that_never_finish_their_headers_do_not_starve_the_server_at_ulimit_n_128() {
    // The default limits (10 s header timeout): the idle connections are still within it when the
    // page is asked for, so it is the connection cap that keeps the server answering.
    let server = Server::start(&[], Some(128));
    assert_eq!(server.get("/").0, 200, "before");
    let mut idle = half_sent_requests(&server, 246);
    for target in ["/", "/api/review.json", "/assets/review.js"] {
        let (status, took) = server.get(target);
        assert_eq!(status, 200, "GET {target} with 246 half-sent requests open");
        assert!(took < Duration::from_secs(3), "GET {target} took {took:?}");
    }
    // The server holds at most 64 of them: the others were closed to make room (EOF or reset).
    let deadline = now() + Duration::from_secs(3);
    let mut closed = vec![false; idle.len()];
    for s in &idle {
        s.set_nonblocking(true).unwrap();
    }
    loop {
        for (s, c) in idle.iter_mut().zip(closed.iter_mut()) {
            if !*c {
                *c = closed_by_server(s);
            }
        }
        let open = closed.iter().filter(|c| !**c).count();
        if open <= 64 {
            break;
        }
        assert!(
            now() < deadline,
            "{open} of 246 half-sent requests still open"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn a_connection_that_sends_nothing_or_half_a_request_is_closed_after_the_header_timeout() {
    let server = Server::start(&["--header-timeout-ms", "500"], None);
    let opened = now();
    let mut silent = server.connect();
    let mut half = half_sent_requests(&server, 1).pop().unwrap();
    for (what, s) in [("silent", &mut silent), ("half-sent", &mut half)] {
        assert!(
            time_to_close(s, Duration::from_secs(5)).is_some(),
            "{what} connection still open after 5 s"
        );
        let took = opened.elapsed();
        assert!(
            took > Duration::from_millis(400) && took < Duration::from_secs(4),
            "{what} connection closed {took:?} after it was opened"
        );
    }
    // A complete request still gets its answer.
    assert_eq!(server.get("/").0, 200);
}

#[test]
fn an_idle_keep_alive_connection_is_closed_after_the_header_timeout() {
    let server = Server::start(&["--header-timeout-ms", "800"], None);
    let mut s = server.connect();
    // Two requests on one connection (keep-alive), then nothing.
    for _ in 0..2 {
        write!(s, "HEAD / HTTP/1.1\r\nHost: {}\r\n\r\n", server.authority).unwrap();
        let mut head = Vec::new();
        let mut byte = [0_u8; 1];
        while !head.ends_with(b"\r\n\r\n") {
            assert_eq!(
                s.read(&mut byte).unwrap(),
                1,
                "connection closed mid-response"
            );
            head.push(byte[0]);
        }
        assert!(
            head.starts_with(b"HTTP/1.1 200"),
            "{}",
            String::from_utf8_lossy(&head)
        );
        std::thread::sleep(Duration::from_millis(300));
    }
    let took = time_to_close(&mut s, Duration::from_secs(5))
        .expect("idle keep-alive connection still open after 5 s");
    assert!(took < Duration::from_secs(4), "closed after {took:?}");
}

#[test]
fn a_client_that_stops_reading_its_responses_is_closed_after_the_stall_timeout() {
    let server = Server::start(&["--stall-timeout-ms", "500"], None);
    // 64 pipelined requests for the 0.7 MB script (~44 MB of responses): far more than the socket
    // buffers hold, so the server's writes stall while the client reads nothing.
    let mut s = server.connect();
    let request = format!(
        "GET /assets/review.js HTTP/1.1\r\nHost: {}\r\n\r\n",
        server.authority
    );
    s.write_all(request.repeat(64).as_bytes()).unwrap();
    std::thread::sleep(Duration::from_secs(2));
    // Now read: what was buffered, then the end (EOF or reset), not all 64 responses.
    let started = now();
    let mut total = 0_usize;
    let mut buf = vec![0_u8; 1 << 16];
    let ended = loop {
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "still reading after 20 s ({total} bytes)"
        );
        match s.read(&mut buf) {
            Ok(0) => break true,
            Ok(n) => total += n,
            Err(e) if e.kind() == ErrorKind::ConnectionReset => break true,
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {
                break false
            }
            Err(e) => panic!("read: {e}"),
        }
    };
    assert!(
        ended,
        "the stalled connection stayed open ({total} bytes read)"
    );
    assert!(
        total < 16 * 687_000,
        "{total} bytes: the server kept writing to a client that did not read"
    );
    assert_eq!(server.get("/").0, 200);
}

#[test]
fn sigterm_or_ctrl_c_during_a_half_sent_request_exits_0_within_2_s() {
    for (signal, name) in [("TERM", "SIGTERM"), ("INT", "Ctrl-C (SIGINT)")] {
        // Default limits: the header timeout (10 s) would not close the half-sent request in time.
        let mut server = Server::start(&[], None);
        let _half = half_sent_requests(&server, 3);
        let _silent = server.connect();
        assert_eq!(server.get("/").0, 200);
        std::thread::sleep(Duration::from_millis(200));
        let (status, took) = server.kill_and_wait(signal, Duration::from_secs(2));
        assert_eq!(status.code(), Some(0), "{name}: {status}");
        assert!(
            took < Duration::from_secs(2),
            "{name}: exited after {took:?}"
        );
        let out = server.rest_of_output();
        assert!(out.contains(&format!("review: stopped by {name}")), "{out}");
    }
}

#[test]
fn the_timeout_flags_are_hidden_from_help() {
    let o = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .args(["review", "--help"])
        .output()
        .unwrap();
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout);
    assert!(help.contains("--allow-host"), "{help}");
    assert!(
        !help.contains("timeout-ms"),
        "hidden flags shown in --help: {help}"
    );
}
