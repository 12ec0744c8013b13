use super::*;
use std::io::{Read, Write};

/// A fresh folder with `a.wasm` (4 bytes) and `index.html` in it.
fn site(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("attlab-serve-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("a.wasm"), b"\0asm").unwrap();
    std::fs::write(dir.join("index.html"), b"<!doctype html>").unwrap();
    dir
}

/// Sends `request` on a new connection and reads the reply until the server closes it
/// (failing after 20 s rather than hanging, should it never answer).
fn exchange(addr: SocketAddr, request: &[u8]) -> String {
    let mut stream = TcpStream::connect(addr).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(20)))
        .unwrap();
    stream.write_all(request).unwrap();
    let mut reply = Vec::new();
    stream
        .read_to_end(&mut reply)
        .expect("the server answers and closes the connection");
    String::from_utf8_lossy(&reply).into_owned()
}

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
fn serves_a_wasm_file_with_its_type_closes_and_stops() {
    let mut server = start(&site("wasm"), 0).unwrap();
    // A keep-alive request still gets one response and the connection closed after it.
    let reply = exchange(server.addr, b"GET /a.wasm HTTP/1.1\r\nHost: x\r\n\r\n");
    assert!(reply.starts_with("HTTP/1.1 200 OK\r\n"), "{reply}");
    assert!(
        reply.contains("Content-Type: application/wasm\r\n"),
        "{reply}"
    );
    assert!(reply.contains("Content-Length: 4\r\n"), "{reply}");
    assert!(reply.contains("Connection: close\r\n"), "{reply}");
    assert!(reply.ends_with("\r\n\r\n\0asm"), "{reply:?}");
    let index = exchange(server.addr, b"GET /?lang=ru HTTP/1.1\r\n\r\n");
    assert!(index.ends_with("<!doctype html>"), "{index}");
    server.stop();
    assert!(TcpStream::connect(server.addr).is_err(), "still listening");
}

#[test]
fn a_versioned_url_is_kept_and_every_other_is_revalidated() {
    let dir = site("cache");
    std::fs::create_dir_all(dir.join("pkg")).unwrap();
    std::fs::write(dir.join("pkg/a.wasm"), b"\0asm").unwrap();
    let server = start(&dir, 0).unwrap();
    let cache = |target: &str| {
        let reply = exchange(
            server.addr,
            format!("GET {target} HTTP/1.1\r\n\r\n").as_bytes(),
        );
        assert!(
            reply.starts_with("HTTP/1.1 200 OK\r\n"),
            "{target}: {reply}"
        );
        reply
            .lines()
            .find_map(|l| l.strip_prefix("Cache-Control: "))
            .map(str::to_string)
    };
    let kept = Some(IMMUTABLE.to_string());
    let asked = Some(REVALIDATE.to_string());
    assert_eq!(cache("/pkg/a.wasm?v=3f9a0c"), kept);
    assert_eq!(cache("/pkg/a.wasm?x=1&v=3f9a0c#frag"), kept);
    assert_eq!(cache("/pkg/a.wasm"), asked);
    assert_eq!(
        cache("/pkg/a.wasm?v="),
        asked,
        "an empty version names nothing"
    );
    assert_eq!(cache("/pkg/a.wasm?vv=1"), asked);
    assert_eq!(cache("/pkg/a.wasm#v=1"), asked, "a fragment is not a query");
    assert_eq!(cache("/a.wasm?v=3f9a0c"), asked, "only pkg/ is versioned");
    assert_eq!(cache("/?lang=ru"), asked);
    // An error is never kept.
    let missing = exchange(server.addr, b"GET /pkg/gone.wasm?v=1 HTTP/1.1\r\n\r\n");
    assert!(missing.contains("Cache-Control: no-cache\r\n"), "{missing}");
}

#[test]
fn head_missing_files_other_methods_and_bad_requests_get_their_status() {
    let server = start(&site("status"), 0).unwrap();
    let head = exchange(server.addr, b"HEAD /a.wasm HTTP/1.1\r\n\r\n");
    assert!(head.starts_with("HTTP/1.1 200 OK\r\n"), "{head}");
    assert!(head.contains("Content-Length: 4\r\n"), "{head}");
    assert!(head.ends_with("\r\n\r\n"), "HEAD sent a body: {head:?}");
    let missing = exchange(server.addr, b"GET /nothing.js HTTP/1.1\r\n\r\n");
    assert!(
        missing.starts_with("HTTP/1.1 404 Not Found\r\n"),
        "{missing}"
    );
    let escape = exchange(server.addr, b"GET /../../etc/passwd HTTP/1.1\r\n\r\n");
    assert!(escape.starts_with("HTTP/1.1 404 "), "{escape}");
    let post = exchange(server.addr, b"POST /a.wasm HTTP/1.1\r\n\r\n");
    assert!(post.starts_with("HTTP/1.1 405 "), "{post}");
    assert!(post.contains("Allow: GET, HEAD\r\n"), "{post}");
    let junk = exchange(server.addr, b"\x01\x02 not http\r\n\r\n");
    assert!(junk.starts_with("HTTP/1.1 400 Bad Request\r\n"), "{junk}");
    let mut many = b"GET / HTTP/1.1\r\n".to_vec();
    for k in 0..2000 {
        many.extend_from_slice(format!("X-{k}: y\r\n").as_bytes());
    }
    let many = exchange(server.addr, &many);
    assert!(many.starts_with("HTTP/1.1 431 "), "{many}");
    let long = format!("GET / HTTP/1.1\r\nX-Long: {}\r\n", "y".repeat(40_000));
    let long = exchange(server.addr, long.as_bytes());
    assert!(long.starts_with("HTTP/1.1 431 "), "{long}");
}

/// The page's hang with tiny_http: a browser holds connections open without sending on
/// them (as Chromium's spare sockets do), and a request on one more must still be
/// answered at once. Twelve silent ones, three times tiny_http's pool of four.
#[test]
fn a_request_is_answered_while_many_connections_stay_silent() {
    let server = start(&site("silent"), 0).unwrap();
    let silent: Vec<TcpStream> = (0..12)
        .map(|_| TcpStream::connect(server.addr).unwrap())
        .collect();
    let reply = exchange(server.addr, b"GET /a.wasm HTTP/1.1\r\n\r\n");
    assert!(reply.starts_with("HTTP/1.1 200 OK\r\n"), "{reply}");
    drop(silent);
}
