//! A small static file server for `dist/` on the loopback interface, with the MIME types a
//! wasm page needs (`application/wasm` for `.wasm`, `text/javascript` for `.js`, …), for
//! `cargo xtask serve` and `cargo xtask test` (whose page tests load the site from it).

use std::fs::File;
use std::net::{SocketAddr, TcpStream};
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;
use std::thread;
use std::time::{Duration, Instant};
use tiny_http::{Header, Request, Response, Server};

/// Worker threads answering requests.
const WORKERS: usize = 4;

/// A running server: its address and worker threads.
pub struct Running {
    /// The bound address (`127.0.0.1:PORT`).
    pub addr: SocketAddr,
    server: Option<Arc<Server>>,
    workers: Vec<thread::JoinHandle<()>>,
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
        for worker in self.workers.drain(..) {
            let _ = worker.join();
        }
    }

    /// Stops serving; returns once the port refuses new connections (at most after 2 s).
    /// Connections a client keeps alive stay open with nobody answering on them (tiny_http
    /// gives no way to close them), so a test that cuts the network under a browser serves
    /// with a server of its own (`tests/tests/page/server.rs`).
    pub fn stop(&mut self) {
        if let Some(server) = self.server.take() {
            for _ in 0..self.workers.len() {
                server.unblock();
            }
        }
        for worker in self.workers.drain(..) {
            let _ = worker.join();
        }
        // The listener closes when tiny_http's accept thread sees the server gone.
        let deadline = Instant::now() + Duration::from_secs(2);
        while TcpStream::connect(self.addr).is_ok() && Instant::now() < deadline {
            thread::sleep(Duration::from_millis(10));
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if self.server.is_some() {
            self.stop();
        }
    }
}

/// Starts serving `dir` on `127.0.0.1:port` (`0` picks a free port) in background threads.
pub fn start(dir: &Path, port: u16) -> Result<Running, String> {
    let server = Server::http(("127.0.0.1", port))
        .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
    let addr = server
        .server_addr()
        .to_ip()
        .ok_or("the server is not on an IP address")?;
    let server = Arc::new(server);
    let root = Arc::new(dir.to_path_buf());
    let workers = (0..WORKERS)
        .map(|_| {
            let server = Arc::clone(&server);
            let root = Arc::clone(&root);
            thread::spawn(move || {
                for request in server.incoming_requests() {
                    respond(&root, request);
                }
            })
        })
        .collect();
    Ok(Running {
        addr,
        server: Some(server),
        workers,
    })
}

/// Answers one request with the file it names, or 404.
fn respond(root: &Path, request: Request) {
    let file = resolve(root, request.url()).and_then(|p| File::open(&p).ok().map(|f| (p, f)));
    let result = match file {
        Some((path, file)) => {
            let response = Response::from_file(file)
                .with_header(header("Content-Type", mime(&path)))
                .with_header(header("Cache-Control", "no-cache"));
            request.respond(response)
        }
        None => {
            let response = Response::from_string("404 not found")
                .with_status_code(404)
                .with_header(header("Content-Type", "text/plain; charset=utf-8"));
            request.respond(response)
        }
    };
    if let Err(e) = result {
        eprintln!("attlab-serve: writing a response failed: {e}");
    }
}

/// An HTTP header from two ASCII strings (only ever called with constants).
fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes())
        .expect("header names and values are ASCII")
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
        "txt" | "md" => "text/plain; charset=utf-8",
        "csv" => "text/csv; charset=utf-8",
        "woff" => "font/woff",
        "woff2" => "font/woff2",
        "ttf" => "font/ttf",
        "otf" => "font/otf",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mime_types() {
        assert_eq!(mime(Path::new("pkg/a_bg.wasm")), "application/wasm");
        assert_eq!(
            mime(Path::new("pkg/a.js")),
            "text/javascript; charset=utf-8"
        );
        assert_eq!(mime(Path::new("index.html")), "text/html; charset=utf-8");
        assert_eq!(mime(Path::new("blob")), "application/octet-stream");
    }

    #[test]
    fn decoding_and_escapes() {
        assert_eq!(percent_decode("/a%20b").as_deref(), Some("/a b"));
        assert_eq!(percent_decode("/bad%2"), None);
        let root = std::env::temp_dir();
        assert_eq!(resolve(&root, "/../etc/passwd"), None);
        assert_eq!(resolve(&root, "/%2e%2e/etc/passwd"), None);
    }

    #[test]
    fn serves_a_wasm_file_with_its_type_and_stops() {
        use std::io::{Read, Write};
        let dir = std::env::temp_dir().join(format!("attlab-serve-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("a.wasm"), b"\0asm").unwrap();
        let mut server = start(&dir, 0).unwrap();
        let mut stream = TcpStream::connect(server.addr).unwrap();
        stream
            .write_all(b"GET /a.wasm HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            .unwrap();
        let mut reply = String::new();
        stream.read_to_string(&mut reply).unwrap();
        assert!(reply.starts_with("HTTP/1.1 200"), "{reply}");
        assert!(reply.contains("application/wasm"), "{reply}");
        server.stop();
        assert!(TcpStream::connect(server.addr).is_err(), "still listening");
    }
}
