//! A small static file server for `dist/` on the loopback interface, with the MIME types a
//! wasm page needs (`application/wasm` for `.wasm`, `text/javascript` for `.js`, …), for
//! `cargo xtask serve` and `cargo xtask test` (whose page tests load the site from it).
//!
//! Each connection gets its own thread and one response, then is closed
//! (`Connection: close`). The server used before, tiny_http 0.12, ran connections on a
//! pool of four threads and held each open for as long as the browser kept it alive; when
//! Chromium opened six connections at once to a freshly started server, the pool could
//! queue one behind the four it was serving, and the request on it (the wasm, in the page
//! tests) waited for ever: the page never started. A thread per connection cannot queue,
//! and a closed connection leaves nothing for a browser to wait on when the server stops
//! (the page tests' network cut). Requests are parsed by `httparse`.

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

use std::fs::File;
use std::io::{self, Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread;
use std::time::Duration;

/// The longest request head (request line and headers) read, in bytes.
const MAX_HEAD_BYTES: usize = 16 * 1024;
/// The most headers a request may have.
const MAX_HEADERS: usize = 64;
/// How long a connection may stay silent, or a write may stall, before it is closed.
const IDLE_TIMEOUT: Duration = Duration::from_secs(30);
/// How long a closing connection waits for the client to finish sending.
const LINGER: Duration = Duration::from_secs(2);
/// The most a closing connection reads and throws away.
const LINGER_BYTES: usize = 1 << 20;
/// How often the accepting thread looks at the stop flag while nobody connects.
const ACCEPT_POLL: Duration = Duration::from_millis(5);

/// A running server: its address and the thread accepting connections.
pub struct Running {
    /// The bound address (`127.0.0.1:PORT`).
    pub addr: SocketAddr,
    stop: Arc<AtomicBool>,
    accept: Option<thread::JoinHandle<()>>,
}

impl Running {
    /// The page URL, with a trailing slash.
    pub fn url(&self) -> String {
        format!("http://{}/", self.addr)
    }

    /// The bound port.
    pub fn port(&self) -> u16 {
        self.addr.port()
    }

    /// Blocks for as long as the server runs (until the process is stopped).
    pub fn wait(mut self) {
        if let Some(accept) = self.accept.take() {
            let _ = accept.join();
        }
    }

    /// Stops serving; returns once the port refuses new connections. A response being
    /// sent is finished; no connection is left open after it.
    pub fn stop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        if let Some(accept) = self.accept.take() {
            let _ = accept.join();
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Starts serving `dir` on `127.0.0.1:port` (`0` picks a free port) in background threads.
pub fn start(dir: &Path, port: u16) -> Result<Running, String> {
    let listener = TcpListener::bind(("127.0.0.1", port))
        .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
    let addr = listener
        .local_addr()
        .map_err(|e| format!("no local address: {e}"))?;
    listener
        .set_nonblocking(true)
        .map_err(|e| format!("cannot poll the listener: {e}"))?;
    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    let root = Arc::new(dir.to_path_buf());
    let accept = thread::Builder::new()
        .name("attlab-serve".into())
        .spawn(move || accept_until_stopped(&listener, &root, &flag))
        .map_err(|e| format!("cannot start the server's thread: {e}"))?;
    Ok(Running {
        addr,
        stop,
        accept: Some(accept),
    })
}

/// Accepts connections until `stop` is set, each answered on a thread of its own; the
/// listener closes when this returns.
fn accept_until_stopped(listener: &TcpListener, root: &Arc<PathBuf>, stop: &AtomicBool) {
    while !stop.load(Ordering::SeqCst) {
        match listener.accept() {
            Ok((stream, _)) => {
                let root = Arc::clone(root);
                let spawned = thread::Builder::new()
                    .name("attlab-serve connection".into())
                    .spawn(move || answer_connection(stream, &root));
                if let Err(e) = spawned {
                    eprintln!("attlab-serve: no thread for a connection: {e}");
                }
            }
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => thread::sleep(ACCEPT_POLL),
            // A connection reset before it was accepted, or no file descriptors left for
            // a moment: the next one may work.
            Err(e) => {
                eprintln!("attlab-serve: accepting a connection failed: {e}");
                thread::sleep(ACCEPT_POLL);
            }
        }
    }
}

/// Reads one request on `stream`, answers it and closes the connection.
fn answer_connection(mut stream: TcpStream, root: &Path) {
    let _ = stream.set_nonblocking(false);
    let _ = stream.set_read_timeout(Some(IDLE_TIMEOUT));
    let _ = stream.set_write_timeout(Some(IDLE_TIMEOUT));
    let reply = match read_request(&mut stream) {
        Ok(Some(request)) => reply_to(root, &request),
        // The client closed the connection, or stayed silent: nothing to answer.
        Ok(None) => return,
        Err(reply) => reply,
    };
    if let Err(e) = reply.send(&mut stream) {
        let gone = matches!(
            e.kind(),
            io::ErrorKind::BrokenPipe | io::ErrorKind::ConnectionReset
        );
        if !gone {
            eprintln!("attlab-serve: writing a response failed: {e}");
        }
    }
    linger(&mut stream);
}

/// Closes `stream` gently: ends the sending side, then reads whatever the client still
/// sends (a request cut short by an error reply) for up to [`LINGER`], so closing does
/// not reset the connection under a reply the client has not read yet.
fn linger(stream: &mut TcpStream) {
    let _ = stream.shutdown(Shutdown::Write);
    let _ = stream.set_read_timeout(Some(LINGER));
    let mut sink = [0u8; 4096];
    let mut left = LINGER_BYTES;
    while left > 0 {
        match stream.read(&mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => left = left.saturating_sub(n),
        }
    }
}

/// A request's method and target.
#[derive(Debug, PartialEq)]
struct Request {
    method: String,
    target: String,
}

/// Reads a request head from `stream`. `Ok(None)` when the connection ends or stays silent
/// before a whole head came; `Err` with the reply for a head that is malformed or too long.
fn read_request(stream: &mut impl Read) -> Result<Option<Request>, Reply> {
    let mut head = Vec::with_capacity(1024);
    let mut chunk = [0u8; 4096];
    loop {
        let n = match stream.read(&mut chunk) {
            Ok(0) | Err(_) => return Ok(None),
            Ok(n) => n,
        };
        head.extend_from_slice(&chunk[..n]);
        let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
        let mut request = httparse::Request::new(&mut headers);
        match request.parse(&head) {
            Ok(httparse::Status::Complete(_)) => {
                return Ok(Some(Request {
                    method: request.method.unwrap_or_default().to_string(),
                    target: request.path.unwrap_or("/").to_string(),
                }));
            }
            Ok(httparse::Status::Partial) if head.len() < MAX_HEAD_BYTES => {}
            Ok(httparse::Status::Partial) => {
                return Err(Reply::text(431, "request header fields too large"));
            }
            Err(httparse::Error::TooManyHeaders) => {
                return Err(Reply::text(431, "too many request header fields"));
            }
            Err(e) => return Err(Reply::text(400, &format!("bad request: {e}"))),
        }
    }
}

/// What to send back.
#[derive(Debug)]
struct Reply {
    status: u16,
    content_type: &'static str,
    length: u64,
    body: Body,
    /// A HEAD request: the headers of the GET, without its body.
    head_only: bool,
    /// Its `Cache-Control` value (see [`cache_control`]).
    cache: &'static str,
}

#[derive(Debug)]
enum Body {
    File(File),
    Text(String),
}

impl Reply {
    /// A short plain-text reply (errors).
    fn text(status: u16, text: &str) -> Reply {
        Reply {
            status,
            content_type: "text/plain; charset=utf-8",
            length: text.len() as u64,
            body: Body::Text(text.to_string()),
            head_only: false,
            cache: REVALIDATE,
        }
    }

    /// Writes the status line, the headers and (unless HEAD) the body.
    fn send(self, out: &mut impl Write) -> io::Result<()> {
        let mut head = format!(
            "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\n\
             Cache-Control: {}\r\nConnection: close\r\n",
            self.status,
            reason(self.status),
            self.content_type,
            self.length,
            self.cache
        );
        if self.status == 405 {
            head.push_str("Allow: GET, HEAD\r\n");
        }
        head.push_str("\r\n");
        out.write_all(head.as_bytes())?;
        if !self.head_only {
            match self.body {
                Body::File(file) => {
                    io::copy(&mut file.take(self.length), out)?;
                }
                Body::Text(text) => out.write_all(text.as_bytes())?,
            }
        }
        out.flush()
    }
}

/// The reason phrase of the statuses this server sends.
fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        404 => "Not Found",
        405 => "Method Not Allowed",
        431 => "Request Header Fields Too Large",
        _ => "Internal Server Error",
    }
}

/// The reply to `request`: the file it names under `root`, or an error.
fn reply_to(root: &Path, request: &Request) -> Reply {
    let head_only = match request.method.as_str() {
        "GET" => false,
        "HEAD" => true,
        _ => return Reply::text(405, "only GET and HEAD are served"),
    };
    let opened = resolve(root, &request.target).and_then(|path| {
        let file = File::open(&path).ok()?;
        let length = file.metadata().ok()?.len();
        Some((path, file, length))
    });
    let Some((path, file, length)) = opened else {
        let mut reply = Reply::text(404, "404 not found");
        reply.head_only = head_only;
        return reply;
    };
    Reply {
        status: 200,
        content_type: mime(&path),
        length,
        body: Body::File(file),
        head_only,
        cache: cache_control(&request.target),
    }
}

/// `Cache-Control` of a file that may change under its URL: the browser asks for it again
/// each time (and, with no validator sent, gets it whole).
const REVALIDATE: &str = "no-cache";
/// `Cache-Control` of a versioned URL, which names one build's bytes for good.
const IMMUTABLE: &str = "public, max-age=31536000, immutable";

/// The `Cache-Control` for a request target. The page asks for its wasm and its JS glue with
/// the build's hash in the query (`pkg/…?v=…`, written into `index.html` by `cargo xtask
/// dist`), so those bytes never change under their URL: the browser keeps them (and V8 its
/// compiled code) without asking again, and a new build is a new URL. Only `pkg/` is
/// versioned that way; everything else (`index.html` itself, the fonts, the service worker)
/// may change under its name, whatever its query.
fn cache_control(target: &str) -> &'static str {
    let Some((path, query)) = target.split('#').next().and_then(|t| t.split_once('?')) else {
        return REVALIDATE;
    };
    let versioned = query
        .split('&')
        .any(|pair| pair.strip_prefix("v=").is_some_and(|v| !v.is_empty()));
    if versioned && path.starts_with("/pkg/") {
        IMMUTABLE
    } else {
        REVALIDATE
    }
}

/// Maps a request URL to a file under `root`; `None` for anything escaping it or missing.
/// Folders map to their `index.html`.
fn resolve(root: &Path, url: &str) -> Option<PathBuf> {
    let path = url.split(['?', '#']).next().unwrap_or("");
    let decoded = percent_decode(path)?;
    let relative = Path::new(decoded.trim_start_matches('/'));
    if relative
        .components()
        .any(|c| !matches!(c, Component::Normal(_)))
    {
        return None;
    }
    let mut full = root.join(relative);
    if full.is_dir() {
        full.push("index.html");
    }
    full.is_file().then_some(full)
}

/// Decodes `%XX` escapes; `None` for malformed escapes or non-UTF-8 results.
fn percent_decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

/// The `Content-Type` for a file, by extension.
fn mime(path: &Path) -> &'static str {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    match ext.to_ascii_lowercase().as_str() {
        "html" | "htm" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "wasm" => "application/wasm",
        "css" => "text/css; charset=utf-8",
        "json" | "map" => "application/json",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "jpg" | "jpeg" => "image/jpeg",
        "gif" => "image/gif",
        "webp" => "image/webp",
        "ico" => "image/x-icon",
        "txt" | "md" | "ftl" => "text/plain; charset=utf-8",
        "csv" => "text/csv; charset=utf-8",
        "woff" => "font/woff",
        "woff2" => "font/woff2",
        "ttf" => "font/ttf",
        "otf" => "font/otf",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests;
