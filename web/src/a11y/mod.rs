//! Accessibility on the web: egui builds an AccessKit tree of every control each frame, but
//! eframe's web runner drops it, so a screen reader found one canvas. This module keeps it:
//! an egui [`Plugin`](egui::Plugin) takes the tree from each frame's output and [`plan`]s a
//! mirror of it — one element per control with its ARIA role, its name, its value and its
//! place on the page — which `dom` writes into hidden elements over the canvas (wasm only).
//! A screen reader's click, value change or focus on a mirrored element comes back as an
//! AccessKit action request in the next frame's input, which egui's widgets already obey.
//!
//! No crate does this for eframe (AccessKit's web adapter never shipped; egui's own web
//! "screen reader" speaks events through speech synthesis and is off by default), so this is
//! a small mirror of our own: sliders are real `<input type=range>` (a screen reader's own
//! keys work on them), everything else a `<div>` with its role and state. Keyboard users do
//! not need it: egui's Tab order, the slider keys and the focus ring serve them in the canvas.

#[cfg(target_arch = "wasm32")]
mod dom;
mod roles;

use egui::accesskit::{self, ActionRequest, NodeId, Role, Toggled, TreeUpdate};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

pub use roles::aria_role;

/// What kind of element mirrors a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Element {
    /// `<input type=range>`: a slider a screen reader moves with its own keys.
    Range,
    /// `<div>` with the ARIA role, if any.
    Div,
    /// Text a screen reader reads (a label): a `<span>` with the text.
    Text,
}

/// A number and its range (a slider, a spin button, a progress bar).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Numeric {
    /// The value now.
    pub value: f64,
    /// The least value, if bounded.
    pub min: Option<f64>,
    /// The greatest value, if bounded.
    pub max: Option<f64>,
    /// The step, if the control has one.
    pub step: Option<f64>,
}

/// One mirrored node: everything its element shows.
#[derive(Clone, Debug, PartialEq)]
pub struct MirrorNode {
    /// The AccessKit node id (the element's id is `ak-<id>`).
    pub id: u64,
    /// The nearest mirrored ancestor (`None`: the mirror's root container).
    pub parent: Option<u64>,
    /// The element kind.
    pub element: Element,
    /// The ARIA role ("" for none).
    pub role: &'static str,
    /// The accessible name: its own label, else the labels it is labelled by.
    pub name: String,
    /// A text value (a label's text, a text field's contents, a combo box's choice).
    pub text: Option<String>,
    /// A numeric value and its range.
    pub numeric: Option<Numeric>,
    /// Checked (a check box), pressed (a toggle button) or mixed.
    pub toggled: Option<Toggled>,
    /// Open (a combo box, a collapsing header).
    pub expanded: Option<bool>,
    /// Not operable now.
    pub disabled: bool,
    /// Can be clicked (a click on the element is sent back).
    pub clickable: bool,
    /// Has the keyboard in the canvas.
    pub focused: bool,
    /// Where it is, in CSS pixels: left, top, width, height.
    pub rect_css: Option<[f32; 4]>,
}

/// Plans the mirror of `update` (egui's whole tree of this frame) in tree order. Containers
/// without a name of their own are not mirrored (their children are kept, under the nearest
/// mirrored ancestor), so the page holds one element per control and per text. `zoom` is
/// egui's points per CSS pixel (larger in presenter mode).
pub fn plan(update: &TreeUpdate, zoom: f32, words: &Words) -> Vec<MirrorNode> {
    let nodes: HashMap<NodeId, &accesskit::Node> =
        update.nodes.iter().map(|(id, n)| (*id, n)).collect();
    let Some(root) = update.tree.as_ref().map(|t| t.root) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    // Depth-first, children in order; (node, nearest mirrored ancestor).
    let mut stack = vec![(root, None)];
    let mut seen = std::collections::HashSet::new();
    while let Some((id, parent)) = stack.pop() {
        let Some(node) = nodes.get(&id) else { continue };
        if !seen.insert(id) || node.is_hidden() {
            continue;
        }
        let mirrored = (id != root)
            .then(|| mirror_node(id, node, parent, (&nodes, words), update.focus, zoom))
            .flatten();
        let next_parent = mirrored.as_ref().map_or(parent, |m| Some(m.id));
        if let Some(m) = mirrored {
            out.push(m);
        }
        for child in node.children().iter().rev() {
            stack.push((*child, next_parent));
        }
    }
    out
}

/// The mirror of one node, or `None` for a container with nothing to say.
fn mirror_node(
    id: NodeId,
    node: &accesskit::Node,
    parent: Option<u64>,
    (nodes, words): (&HashMap<NodeId, &accesskit::Node>, &Words),
    focus: NodeId,
    zoom: f32,
) -> Option<MirrorNode> {
    let role = node.role();
    let name = words.spoken(&name_of(node, nodes));
    let element = match role {
        Role::Slider => Element::Range,
        Role::Label => Element::Text,
        _ => Element::Div,
    };
    let aria = aria_role(role);
    let text = node.value().map(|v| words.spoken(v));
    let worth_keeping = !aria.is_empty() || text.is_some() || element != Element::Div;
    if !worth_keeping || (roles::is_container(role) && name.is_empty()) {
        return None;
    }
    let numeric = node.numeric_value().map(|value| Numeric {
        value,
        min: node.min_numeric_value(),
        max: node.max_numeric_value(),
        step: node.numeric_value_step(),
    });
    let rect_css = node.bounds().map(|b| {
        let z = f64::from(zoom);
        [b.x0 * z, b.y0 * z, (b.x1 - b.x0) * z, (b.y1 - b.y0) * z].map(|v| v as f32)
    });
    Some(MirrorNode {
        id: id.0,
        parent,
        element,
        role: aria,
        name,
        text,
        numeric,
        toggled: node.toggled(),
        expanded: node.is_expanded(),
        disabled: node.is_disabled(),
        clickable: node.supports_action(accesskit::Action::Click),
        focused: id == focus,
        rect_css,
    })
}

/// What the mirror says in the reader's language where egui's tree has English of its own
/// or marks a screen reader drops: the combining dot and double dot of φ̇, φ̈, ω̇ (the
/// mirror had read "P_φ̇φ̇" as "P_φφ").
#[derive(Clone, Debug, PartialEq)]
pub struct Words {
    /// Said after a letter with a dot above (U+0307): "dot".
    pub dot: String,
    /// Said after a letter with two dots above (U+0308): "double dot".
    pub double_dot: String,
    /// egui's name of a panel's resize handle, "Resize panel", in the reader's language.
    pub resize_panel: String,
}

impl Default for Words {
    fn default() -> Self {
        Self {
            dot: "dot".into(),
            double_dot: "double dot".into(),
            resize_panel: "Resize panel".into(),
        }
    }
}

impl Words {
    /// `text` as a screen reader should say it.
    pub fn spoken(&self, text: &str) -> String {
        if text == "Resize panel" {
            return self.resize_panel.clone();
        }
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            match c {
                '\u{0307}' => out.push_str(&format!(" {} ", self.dot)),
                '\u{0308}' => out.push_str(&format!(" {} ", self.double_dot)),
                c => out.push(c),
            }
        }
        out.split(' ')
            .filter(|w| !w.is_empty())
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// Keeps `words` for the mirror to use from the next frame (the app sets them from its
    /// catalogue each frame).
    pub fn set(ctx: &egui::Context, words: Self) {
        ctx.data_mut(|d| d.insert_temp(Self::id(), words));
    }

    fn get(ctx: &egui::Context) -> Self {
        ctx.data(|d| d.get_temp(Self::id())).unwrap_or_default()
    }

    fn id() -> egui::Id {
        egui::Id::unique("attlab mirror words")
    }
}

/// A node's accessible name: its label, else the texts of the nodes it is labelled by.
fn name_of(node: &accesskit::Node, nodes: &HashMap<NodeId, &accesskit::Node>) -> String {
    if let Some(label) = node.label() {
        return label.to_string();
    }
    node.labelled_by()
        .iter()
        .filter_map(|l| nodes.get(l))
        .filter_map(|l| l.label().or(l.value()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A number as a screen reader should read it: egui hands some values over through `f32`
/// (0.02 arrives as 0.019999999552965164), so seven significant digits, without trailing
/// zeros.
pub fn tidy(v: f64) -> String {
    format!("{v:.6e}").parse::<f64>().unwrap_or(v).to_string()
}

/// What a screen reader asked of a mirrored element, waiting for the next frame.
#[derive(Clone, Debug, Default)]
pub struct Requests(Arc<Mutex<Vec<ActionRequest>>>);

impl Requests {
    /// Queues a request (from a DOM event).
    pub fn push(&self, request: ActionRequest) {
        if let Ok(mut q) = self.0.lock() {
            q.push(request);
        }
    }

    /// Takes every queued request.
    pub fn take(&self) -> Vec<ActionRequest> {
        self.0
            .lock()
            .map(|mut q| std::mem::take(&mut *q))
            .unwrap_or_default()
    }
}

/// The last mirror planned, for the page and for tests.
pub type LastPlan = Arc<Mutex<Vec<MirrorNode>>>;

/// The egui plugin: requests into each frame's input, the tree out of each frame's output.
#[derive(Debug, Default)]
pub struct Mirror {
    requests: Requests,
    last: LastPlan,
}

impl Mirror {
    /// Installs the mirror on `ctx` (turning egui's AccessKit tree on) and returns where its
    /// plans land.
    pub fn install(ctx: &egui::Context) -> (Requests, LastPlan) {
        let mirror = Self::default();
        let handles = (mirror.requests.clone(), mirror.last.clone());
        ctx.enable_accesskit();
        ctx.add_plugin(mirror);
        handles
    }
}

impl egui::Plugin for Mirror {
    fn debug_name(&self) -> &'static str {
        "attlab accessibility mirror"
    }

    fn input_hook(&mut self, _ctx: &egui::Context, input: &mut egui::RawInput) {
        let requests = self.requests.take();
        input.events.extend(
            requests
                .into_iter()
                .map(egui::Event::AccessKitActionRequest),
        );
    }

    fn output_hook(&mut self, ctx: &egui::Context, output: &mut egui::FullOutput) {
        let Some(update) = output.platform_output.accesskit_update.as_ref() else {
            return;
        };
        let planned = plan(update, ctx.zoom_factor(), &Words::get(ctx));
        #[cfg(target_arch = "wasm32")]
        dom::sync(&planned, &self.requests, ctx);
        if let Ok(mut last) = self.last.lock() {
            *last = planned;
        }
    }
}

/// Sets the live description of the run (a polite live region: a screen reader reads it
/// when it changes, without moving the reader's place). A no-op on the desktop.
pub fn describe(text: &str) {
    #[cfg(target_arch = "wasm32")]
    dom::describe(text);
    #[cfg(not(target_arch = "wasm32"))]
    let _ = text;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dot_above_is_said_and_egui_s_english_is_the_readers() {
        let words = Words {
            dot: "с точкой".into(),
            double_dot: "с двумя точками".into(),
            resize_panel: "Изменить ширину панели".into(),
        };
        assert_eq!(words.spoken("c = P_φ̇φ̇"), "c = P_φ с точкой φ с точкой");
        assert_eq!(words.spoken("φ̈ = 0"), "φ с двумя точками = 0");
        assert_eq!(words.spoken("Resize panel"), "Изменить ширину панели");
        assert_eq!(Words::default().spoken("ω̇ (rad/s²)"), "ω dot (rad/s²)");
        assert_eq!(words.spoken("Gyro σ"), "Gyro σ");
    }

    #[test]
    fn numbers_read_like_the_slider_shows_them() {
        assert_eq!(tidy(f64::from(0.02_f32)), "0.02");
        assert_eq!(tidy(100.0), "100");
        assert_eq!(tidy(-1.5e-7), "-0.00000015");
        assert_eq!(tidy(1234.5678), "1234.568");
    }
}
