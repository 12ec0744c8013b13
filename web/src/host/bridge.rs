//! The browser's side of the host API: listens for `message` events on the window, keeps
//! them for the frame loop (which asks for a frame when one arrives, so a paused page
//! answers too), and posts answers and events back. Only a page whose origin the link
//! allows (or the page's own) is obeyed and hears the events; any other is answered with
//! an `origin-not-allowed` error and nothing else. On the desktop there is no host.

use serde_json::Value;

/// A message from a host page, as it arrived.
#[derive(Debug)]
pub struct Incoming {
    /// The sending page's origin (`null` for a page from a file).
    pub origin: String,
    /// The message's data as JSON text (`None`: a value JSON cannot hold, a function or a
    /// cycle).
    pub data: Option<String>,
    /// Where the answer goes.
    #[cfg(target_arch = "wasm32")]
    source: Option<web_sys::Window>,
}

/// The page's link to the window that embeds it and to whoever writes to it.
#[derive(Default)]
pub struct Bridge {
    #[cfg(target_arch = "wasm32")]
    inner: Option<wasm::Inner>,
    /// The embedding page's origin was refused once (said once in the console).
    refused_parent: bool,
}

impl Bridge {
    /// Starts listening (in the page); `ctx` is asked for a frame when a message arrives.
    pub fn install(ctx: &egui::Context) -> Self {
        #[cfg(target_arch = "wasm32")]
        {
            Self {
                inner: wasm::Inner::install(ctx),
                refused_parent: false,
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = ctx;
            Self::default()
        }
    }

    /// The messages that arrived since the last call.
    pub fn take(&mut self) -> Vec<Incoming> {
        #[cfg(target_arch = "wasm32")]
        if let Some(inner) = &self.inner {
            return std::mem::take(&mut *inner.inbox.borrow_mut());
        }
        Vec::new()
    }

    /// The page's own origin (`""` on the desktop).
    pub fn own_origin(&self) -> String {
        #[cfg(target_arch = "wasm32")]
        if let Some(inner) = &self.inner {
            return inner.own_origin.clone();
        }
        String::new()
    }

    /// Answers `to` with `message`.
    pub fn answer(&self, to: &Incoming, message: &Value) {
        #[cfg(target_arch = "wasm32")]
        if let Some(source) = &to.source {
            wasm::post(source, &to.origin, message);
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (to, message);
    }

    /// Posts `events` to the page that embeds this one, if its origin is allowed (`allowed`
    /// says which are); when it is not, the console says once why it hears nothing. Returns
    /// whether an embedding page hears them (then the page keeps drawing a frame a second,
    /// paused or not, for its ticks).
    pub fn report(&mut self, events: &[Value], allowed: impl Fn(&str) -> bool) -> bool {
        #[cfg(target_arch = "wasm32")]
        if let Some((parent, origin)) = self.inner.as_ref().and_then(wasm::Inner::parent) {
            if allowed(&origin) {
                for e in events {
                    wasm::post(&parent, &origin, e);
                }
                return true;
            } else if !self.refused_parent {
                self.refused_parent = true;
                log::info!(
                    "Attitude Lab: the page that embeds this one ({origin}) is not allowed by the link, so it hears no events; add origin={origin} to the link (docs/embed.md)"
                );
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (events, allowed, &mut self.refused_parent);
        false
    }
}

#[cfg(target_arch = "wasm32")]
mod wasm {
    use super::Incoming;
    use serde_json::Value;
    use std::cell::RefCell;
    use std::rc::Rc;
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::closure::Closure;

    /// The listener's queue and what the page knows of itself.
    pub(super) struct Inner {
        pub(super) inbox: Rc<RefCell<Vec<Incoming>>>,
        pub(super) own_origin: String,
        window: web_sys::Window,
    }

    impl Inner {
        pub(super) fn install(ctx: &egui::Context) -> Option<Self> {
            let window = web_sys::window()?;
            let own_origin = window.location().origin().ok()?;
            let inbox: Rc<RefCell<Vec<Incoming>>> = Rc::default();
            let (queue, ctx, me) = (inbox.clone(), ctx.clone(), window.clone());
            let listener = Closure::<dyn FnMut(web_sys::MessageEvent)>::new(
                move |event: web_sys::MessageEvent| {
                    // A window of another origin is not `instanceof Window` here (its proxy
                    // hides its prototype), yet it takes `postMessage`: no checked cast.
                    let source = (event.source())
                        .filter(|s| !s.is_undefined() && !s.is_null())
                        .map(|s| s.unchecked_into::<web_sys::Window>());
                    // The page's own posts (its answers to itself) are not requests.
                    if source
                        .as_ref()
                        .is_some_and(|s| js_sys::Object::is(s.as_ref(), me.as_ref()))
                    {
                        return;
                    }
                    let data = event.data();
                    let data = match data.as_string() {
                        Some(text) => Some(serde_json::Value::String(text).to_string()),
                        None => js_sys::JSON::stringify(&data)
                            .ok()
                            .and_then(|s| s.as_string()),
                    };
                    queue.borrow_mut().push(Incoming {
                        origin: event.origin(),
                        data,
                        source,
                    });
                    ctx.request_repaint();
                },
            );
            window
                .add_event_listener_with_callback("message", listener.as_ref().unchecked_ref())
                .ok()?;
            // Listens for the page's whole life.
            listener.forget();
            Some(Self {
                inbox,
                own_origin,
                window,
            })
        }

        /// The window that embeds this page and its origin, if the page is embedded.
        pub(super) fn parent(&self) -> Option<(web_sys::Window, String)> {
            let parent = self.window.parent().ok()??;
            if js_sys::Object::is(parent.as_ref(), self.window.as_ref()) {
                return None;
            }
            // Chromium and Safari name the embedding origins; Firefox gives the referrer.
            let location = self.window.location();
            let origin = js_sys::Reflect::get(location.as_ref(), &"ancestorOrigins".into())
                .ok()
                .and_then(|list| list.dyn_into::<web_sys::DomStringList>().ok())
                .and_then(|list| list.item(0))
                .or_else(|| {
                    let referrer = self.window.document()?.referrer();
                    web_sys::Url::new(&referrer).ok().map(|u| u.origin())
                })?;
            Some((parent, origin))
        }
    }

    /// Posts `message` (as a structured object) to `to`, whose origin is `origin`.
    pub(super) fn post(to: &web_sys::Window, origin: &str, message: &Value) {
        let Ok(object) = js_sys::JSON::parse(&message.to_string()) else {
            return;
        };
        // A page from a file has the opaque origin `null`, which no target names.
        let target = if origin == "null" { "*" } else { origin };
        let _ = to.post_message(&object, target);
    }
}
