//! Reads the `target_features` custom section that rustc/wasm-ld write into a wasm module,
//! and turns it into the `wasm-opt --enable-…` flags the module needs.

/// Flags always passed to `wasm-opt`: the features Rust's wasm32 target enables by default.
pub const BASELINE_FLAGS: &[&str] = &[
    "--enable-bulk-memory",
    "--enable-nontrapping-float-to-int",
    "--enable-sign-ext",
    "--enable-mutable-globals",
    "--enable-reference-types",
    "--enable-multivalue",
];

/// LLVM feature name → binaryen flag.
const FEATURE_FLAGS: &[(&str, &str)] = &[
    ("bulk-memory", "--enable-bulk-memory"),
    ("bulk-memory-opt", "--enable-bulk-memory-opt"),
    ("call-indirect-overlong", "--enable-call-indirect-overlong"),
    ("nontrapping-fptoint", "--enable-nontrapping-float-to-int"),
    ("sign-ext", "--enable-sign-ext"),
    ("mutable-globals", "--enable-mutable-globals"),
    ("reference-types", "--enable-reference-types"),
    ("multivalue", "--enable-multivalue"),
    ("simd128", "--enable-simd"),
    ("relaxed-simd", "--enable-relaxed-simd"),
    ("tail-call", "--enable-tail-call"),
    ("extended-const", "--enable-extended-const"),
    ("atomics", "--enable-threads"),
    ("exception-handling", "--enable-exception-handling"),
    ("multimemory", "--enable-multimemory"),
    ("fp16", "--enable-fp16"),
    ("gc", "--enable-gc"),
];

/// Reads an unsigned LEB128 number at `*pos`, advancing it.
fn leb_u32(bytes: &[u8], pos: &mut usize) -> Option<u32> {
    let mut value: u32 = 0;
    for shift in (0..35).step_by(7) {
        let byte = *bytes.get(*pos)?;
        *pos += 1;
        value |= u32::from(byte & 0x7f).checked_shl(shift)?;
        if byte & 0x80 == 0 {
            return Some(value);
        }
    }
    None
}

/// Reads a length-prefixed byte string at `*pos`, advancing it.
fn bytes_at<'a>(bytes: &'a [u8], pos: &mut usize) -> Option<&'a [u8]> {
    let len = usize::try_from(leb_u32(bytes, pos)?).ok()?;
    let out = bytes.get(*pos..pos.checked_add(len)?)?;
    *pos += len;
    Some(out)
}

/// The payload of the custom section called `name`, if the module has one.
fn custom_section<'a>(module: &'a [u8], name: &str) -> Option<&'a [u8]> {
    if module.get(..4)? != b"\0asm" {
        return None;
    }
    let mut pos = 8;
    while pos < module.len() {
        let id = module[pos];
        pos += 1;
        let payload = bytes_at(module, &mut pos)?;
        if id == 0 {
            let mut inner = 0;
            if bytes_at(payload, &mut inner)? == name.as_bytes() {
                return payload.get(inner..);
            }
        }
    }
    None
}

/// The features the module declares as used or required (`+` or `=` prefix).
pub fn used_features(module: &[u8]) -> Vec<String> {
    let Some(section) = custom_section(module, "target_features") else {
        return Vec::new();
    };
    let mut pos = 0;
    let count = leb_u32(section, &mut pos).unwrap_or(0);
    let mut out = Vec::new();
    for _ in 0..count {
        let Some(&prefix) = section.get(pos) else {
            break;
        };
        pos += 1;
        let Some(name) = bytes_at(section, &mut pos) else {
            break;
        };
        if prefix == b'+' || prefix == b'=' {
            out.push(String::from_utf8_lossy(name).into_owned());
        }
    }
    out
}

/// The `wasm-opt` feature flags for `module`: the baseline plus whatever it declares.
/// Features binaryen has no flag for are returned separately so the caller can warn.
pub fn opt_flags(module: &[u8]) -> (Vec<String>, Vec<String>) {
    let mut flags: Vec<String> = BASELINE_FLAGS.iter().map(|f| (*f).to_string()).collect();
    let mut unknown = Vec::new();
    for feature in used_features(module) {
        match FEATURE_FLAGS.iter().find(|(name, _)| *name == feature) {
            Some((_, flag)) if !flags.iter().any(|f| f == flag) => flags.push((*flag).to_string()),
            Some(_) => {}
            None => unknown.push(feature),
        }
    }
    (flags, unknown)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A module with only a `target_features` section declaring `+sign-ext` and `-simd128`.
    fn module() -> Vec<u8> {
        let mut payload = vec![15];
        payload.extend_from_slice(b"target_features");
        payload.push(2);
        payload.push(b'+');
        payload.push(8);
        payload.extend_from_slice(b"sign-ext");
        payload.push(b'-');
        payload.push(7);
        payload.extend_from_slice(b"simd128");
        let mut module = b"\0asm\x01\0\0\0".to_vec();
        module.push(0);
        module.push(u8::try_from(payload.len()).unwrap_or(0));
        module.extend(payload);
        module
    }

    #[test]
    fn reads_declared_features() {
        assert_eq!(used_features(&module()), vec!["sign-ext".to_string()]);
        let (flags, unknown) = opt_flags(&module());
        assert_eq!(flags.len(), BASELINE_FLAGS.len());
        assert!(unknown.is_empty());
    }

    #[test]
    fn no_section_means_baseline() {
        assert!(used_features(b"\0asm\x01\0\0\0").is_empty());
        assert!(used_features(b"not wasm").is_empty());
    }
}
