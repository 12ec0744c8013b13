//! The mirror in the page: one hidden element per planned node inside `#attlab_a11y` (see
//! `index.html`: transparent, fixed over the canvas, not hit by the pointer), written only
//! where something changed since the last frame. The canvas names the mirror as its own
//! (`aria-owns`) and the element of the control with the keyboard as its active
//! descendant, so a screen reader announces what Tab reached. A click, a value set or a
//! focus on an element becomes an AccessKit request for the next frame.

use super::{Element, MirrorNode, Requests};
use egui::accesskit::{Action, ActionData, ActionRequest, NodeId, Toggled, TreeId};
use std::cell::RefCell;
use std::collections::{HashMap, HashSet};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::Closure;

/// The id of the mirror's container in `index.html`.
pub const ROOT_ID: &str = "attlab_a11y";
/// The id of the live description (`role=status`) in `index.html`.
pub const LIVE_ID: &str = "attlab_live";
/// The canvas the app draws on.
pub const CANVAS_ID: &str = "attlab_canvas";

thread_local! {
    static DOM: RefCell<Option<Dom>> = const { RefCell::new(None) };
}

type Listener = Closure<dyn FnMut(web_sys::Event)>;

/// The elements written so far.
struct Dom {
    document: web_sys::Document,
    root: web_sys::Element,
    elements: HashMap<u64, (web_sys::Element, MirrorNode)>,
    children: HashMap<Option<u64>, Vec<u64>>,
    active: Option<u64>,
    _listeners: Vec<Listener>,
}

/// Writes `plan` into the page (creating the mirror on the first call).
pub fn sync(plan: &[MirrorNode], requests: &Requests, ctx: &egui::Context) {
    DOM.with(|dom| {
        let mut dom = dom.borrow_mut();
        if dom.is_none() {
            *dom = Dom::create(requests, ctx);
        }
        if let Some(dom) = dom.as_mut() {
            dom.apply(plan);
        }
    });
}

/// Sets the text of the live description.
pub fn describe(text: &str) {
    let live = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id(LIVE_ID));
    if let Some(live) = live
        && live.text_content().as_deref() != Some(text)
    {
        live.set_text_content(Some(text));
    }
}

impl Dom {
    /// The mirror over the page's container, with its three listeners (events bubble up to
    /// it from every element, so no element needs its own).
    fn create(requests: &Requests, ctx: &egui::Context) -> Option<Self> {
        let document = web_sys::window()?.document()?;
        let root = document.get_element_by_id(ROOT_ID)?;
        let mut listeners = Vec::new();
        for (event, action) in [
            ("click", Action::Click),
            ("input", Action::SetValue),
            ("focusin", Action::Focus),
        ] {
            let (requests, ctx) = (requests.clone(), ctx.clone());
            let listener: Listener = Closure::new(move |e: web_sys::Event| {
                if let Some(request) = request_of(&e, action) {
                    requests.push(request);
                    ctx.request_repaint();
                }
            });
            root.add_event_listener_with_callback(event, listener.as_ref().unchecked_ref())
                .ok()?;
            listeners.push(listener);
        }
        Some(Self {
            document,
            root,
            elements: HashMap::new(),
            children: HashMap::new(),
            active: None,
            _listeners: listeners,
        })
    }

    fn apply(&mut self, plan: &[MirrorNode]) {
        let mut wanted: HashMap<Option<u64>, Vec<u64>> = HashMap::new();
        let live: HashSet<u64> = plan.iter().map(|n| n.id).collect();
        for node in plan {
            self.write(node);
            wanted.entry(node.parent).or_default().push(node.id);
        }
        self.elements.retain(|id, (element, _)| {
            let keep = live.contains(id);
            if !keep {
                element.remove();
            }
            keep
        });
        for (parent, kids) in &wanted {
            if self.children.get(parent) == Some(kids) {
                continue;
            }
            let holder = parent
                .and_then(|p| self.elements.get(&p).map(|e| e.0.clone()))
                .unwrap_or_else(|| self.root.clone());
            for kid in kids {
                if let Some((element, _)) = self.elements.get(kid) {
                    let _ = holder.append_child(element);
                }
            }
        }
        self.children = wanted;
        self.point_at_focus(plan.iter().find(|n| n.focused).map(|n| n.id));
    }

    /// Creates or updates the element of `node`.
    fn write(&mut self, node: &MirrorNode) {
        let stale = self
            .elements
            .get(&node.id)
            .is_some_and(|(_, old)| old.element != node.element);
        if stale && let Some((element, _)) = self.elements.remove(&node.id) {
            element.remove();
        }
        if let Some((element, old)) = self.elements.get_mut(&node.id) {
            if old != node {
                attributes(element, node, Some(old));
                *old = node.clone();
            }
            return;
        }
        let Some(element) = self.create_element(node) else {
            return;
        };
        attributes(&element, node, None);
        self.elements.insert(node.id, (element, node.clone()));
    }

    fn create_element(&self, node: &MirrorNode) -> Option<web_sys::Element> {
        let tag = match node.element {
            Element::Range => "input",
            Element::Div => "div",
            Element::Text => "span",
        };
        let element = self.document.create_element(tag).ok()?;
        let _ = element.set_attribute("id", &format!("ak-{}", node.id));
        let _ = element.set_attribute("data-ak", &node.id.to_string());
        if node.element == Element::Range {
            let _ = element.set_attribute("type", "range");
        }
        Some(element)
    }

    /// Tells the canvas which element has the keyboard (its active descendant).
    fn point_at_focus(&mut self, focused: Option<u64>) {
        if self.active == focused {
            return;
        }
        self.active = focused;
        let Some(canvas) = self.document.get_element_by_id(CANVAS_ID) else {
            return;
        };
        let _ = match focused {
            Some(id) => canvas.set_attribute("aria-activedescendant", &format!("ak-{id}")),
            None => canvas.remove_attribute("aria-activedescendant"),
        };
    }
}

/// Writes what differs between `old` (nothing, for a new element) and `node`.
fn attributes(element: &web_sys::Element, node: &MirrorNode, old: Option<&MirrorNode>) {
    let changed = |f: &dyn Fn(&MirrorNode) -> String| old.is_none_or(|o| f(o) != f(node));
    let set = |name: &str, value: Option<String>| {
        let _ = match value {
            Some(v) => element.set_attribute(name, &v),
            None => element.remove_attribute(name),
        };
    };
    if changed(&|n| n.role.to_string()) {
        set("role", (!node.role.is_empty()).then(|| node.role.into()));
    }
    if changed(&|n| format!("{}|{:?}", n.name, n.text)) {
        write_name_and_text(element, node);
    }
    if changed(&|n| format!("{:?}", n.numeric)) {
        write_numeric(element, node);
    }
    if changed(&|n| format!("{:?}{:?}", n.toggled, n.role)) {
        let state = node.toggled.map(|t| {
            match t {
                Toggled::True => "true",
                Toggled::False => "false",
                Toggled::Mixed => "mixed",
            }
            .to_string()
        });
        let (checked, pressed) = if node.role == "button" {
            (None, state)
        } else {
            (state, None)
        };
        set("aria-checked", checked);
        set("aria-pressed", pressed);
    }
    if changed(&|n| format!("{:?}", n.expanded)) {
        set("aria-expanded", node.expanded.map(|e| e.to_string()));
    }
    if changed(&|n| format!("{}{}", n.disabled, n.clickable)) {
        set("aria-disabled", node.disabled.then(|| "true".into()));
        // A disabled range input takes no value from a screen reader's keys at all (a
        // locked slider had moved through it).
        if node.element == Element::Range {
            set("disabled", node.disabled.then(String::new));
        }
        let focusable = node.clickable || node.element == Element::Range;
        set("tabindex", focusable.then(|| "-1".into()));
    }
    if changed(&|n| format!("{:?}", n.rect_css)) {
        set(
            "style",
            node.rect_css.map(|[x, y, w, h]| {
                format!("left:{x:.0}px;top:{y:.0}px;width:{w:.0}px;height:{h:.0}px")
            }),
        );
    }
}

/// The name as `aria-label` (a text's own words as its content), and a text value (a
/// combo box's choice, a text field's contents) as the element's text.
fn write_name_and_text(element: &web_sys::Element, node: &MirrorNode) {
    if node.element == Element::Text {
        let words = node.text.as_deref().unwrap_or(&node.name);
        element.set_text_content(Some(words));
        return;
    }
    let _ = if node.name.is_empty() {
        element.remove_attribute("aria-label")
    } else {
        element.set_attribute("aria-label", &node.name)
    };
    match node.element {
        Element::Div => element.set_text_content(node.text.as_deref()),
        // A slider's text is its value in words with its unit ("0.02 °/s").
        Element::Range => {
            let _ = match node.text.as_deref() {
                Some(t) => element.set_attribute("aria-valuetext", t),
                None => element.remove_attribute("aria-valuetext"),
            };
        }
        Element::Text => {}
    }
}

/// A slider's value and range on its `<input>`; a spin button's or a bar's as ARIA values.
fn write_numeric(element: &web_sys::Element, node: &MirrorNode) {
    let Some(n) = node.numeric else {
        for name in ["aria-valuenow", "aria-valuemin", "aria-valuemax"] {
            let _ = element.remove_attribute(name);
        }
        return;
    };
    let num = |v: Option<f64>| v.filter(|v| v.is_finite()).map(super::tidy);
    if node.element == Element::Range {
        let step = num(n.step).unwrap_or_else(|| "any".into());
        for (name, value) in [
            ("min", num(n.min)),
            ("max", num(n.max)),
            ("step", Some(step)),
        ] {
            if let Some(v) = value {
                let _ = element.set_attribute(name, &v);
            }
        }
        if let Some(input) = element.dyn_ref::<web_sys::HtmlInputElement>() {
            input.set_value(&super::tidy(n.value));
        }
        return;
    }
    for (name, value) in [
        ("aria-valuenow", num(Some(n.value))),
        ("aria-valuemin", num(n.min)),
        ("aria-valuemax", num(n.max)),
    ] {
        let _ = match value {
            Some(v) => element.set_attribute(name, &v),
            None => element.remove_attribute(name),
        };
    }
}

/// The AccessKit request a DOM event on a mirrored element stands for.
fn request_of(event: &web_sys::Event, action: Action) -> Option<ActionRequest> {
    let target = event.target()?.dyn_into::<web_sys::Element>().ok()?;
    let element = target.closest("[data-ak]").ok()??;
    // A disabled control (a locked or inactive slider) takes no value and no click; it may
    // still have the keyboard, so a screen reader reads it.
    let disabled =
        element.has_attribute("disabled") || element.get_attribute("aria-disabled").is_some();
    if disabled && action != Action::Focus {
        return None;
    }
    let id: u64 = element.get_attribute("data-ak")?.parse().ok()?;
    let data = match action {
        Action::SetValue => {
            let input = element.dyn_ref::<web_sys::HtmlInputElement>()?;
            Some(ActionData::NumericValue(input.value().parse().ok()?))
        }
        _ => None,
    };
    Some(ActionRequest {
        action,
        target_tree: TreeId::ROOT,
        target_node: NodeId(id),
        data,
    })
}
