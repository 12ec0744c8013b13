//! The page draws with the patched egui-wgpu in `vendor/` (see vendor/README.md): the
//! fragment shader it uses samples the texture in hardware only. Its software filtering, four
//! wrapped `textureLoad`s for kittest's snapshots, is in separate entry points, because a
//! software rasteriser (SwiftShader: a browser with no GPU) ran it for every pixel behind a
//! uniform branch, which made each shaded pixel about seven times as costly.

use naga::{Block, Expression, Function, Handle, Module, Statement};
use std::collections::HashSet;

/// The vendored egui-wgpu's shader, parsed as wgpu parses it.
fn shader() -> Module {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../vendor/egui-wgpu/src/egui.wgsl"
    );
    let text = std::fs::read_to_string(path).expect("vendor/egui-wgpu/src/egui.wgsl");
    naga::front::wgsl::parse_str(&text).expect("egui.wgsl parses")
}

/// Every function `block` calls, nested blocks included.
fn calls(block: &Block, found: &mut impl FnMut(Handle<Function>)) {
    for statement in block.iter() {
        match statement {
            Statement::Call { function, .. } => found(*function),
            Statement::Block(inner) => calls(inner, found),
            Statement::If { accept, reject, .. } => {
                calls(accept, found);
                calls(reject, found);
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                calls(body, found);
                calls(continuing, found);
            }
            Statement::Switch { cases, .. } => {
                for case in cases {
                    calls(&case.body, found);
                }
            }
            _ => {}
        }
    }
}

/// Whether entry point `entry`, or any function it reaches, loads texels (`textureLoad`).
fn loads_texels(module: &Module, entry: &str) -> bool {
    let entry_point = module
        .entry_points
        .iter()
        .find(|e| e.name == entry)
        .unwrap_or_else(|| panic!("egui.wgsl has no entry point {entry}"));
    let mut stack = vec![&entry_point.function];
    let mut seen = HashSet::new();
    while let Some(function) = stack.pop() {
        let loads = |(_, e): (_, &Expression)| matches!(e, Expression::ImageLoad { .. });
        if function.expressions.iter().any(loads) {
            return true;
        }
        calls(&function.body, &mut |h| {
            if seen.insert(h) {
                stack.push(&module.functions[h]);
            }
        });
    }
    false
}

#[test]
fn the_pages_fragment_shader_samples_in_hardware_alone() {
    let module = shader();
    for entry in ["fs_main_gamma_framebuffer", "fs_main_linear_framebuffer"] {
        assert!(
            !loads_texels(&module, entry),
            "{entry} reaches the software filtering (textureLoad): every shaded pixel pays for it"
        );
    }
    // The search finds the loads where they are: kittest's entry points keep them.
    for entry in [
        "fs_main_gamma_framebuffer_predictable",
        "fs_main_linear_framebuffer_predictable",
    ] {
        assert!(
            loads_texels(&module, entry),
            "{entry} lost its software filtering"
        );
    }
}

#[test]
fn the_build_uses_the_patched_egui_wgpu() {
    let lock = include_str!("../../../Cargo.lock");
    let entry = lock
        .split("\n\n")
        .find(|p| p.contains("\nname = \"egui-wgpu\"\n"))
        .expect("egui-wgpu in Cargo.lock");
    assert!(
        !entry.contains("\nsource = "),
        "egui-wgpu comes from a registry, not vendor/ ([patch.crates-io] lost?):\n{entry}"
    );
}
