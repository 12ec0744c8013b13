//! Pictures out: a PNG of one view, or of every plot tab stacked in one image, cut from the
//! frames the renderer drew (egui's screenshot command, in the page and on the desktop).
//!
//! A capture runs over several frames: for the plots, each tab is shown, left to settle for
//! a frame, captured and cut to the plot area; then the tab the user had comes back. The
//! simulation holds still meanwhile, so every part shows the same instant.

use crate::state::PngTarget;
use attlab::model::PlotTab;
use egui::{Color32, ColorImage, Rect};
use std::sync::{Arc, Mutex};

/// Frames drawn after a tab switch before its capture is asked for.
const SETTLE_FRAMES: u32 = 2;
/// Frames to wait for one screenshot before giving up.
const MAX_WAIT_FRAMES: u32 = 120;
/// Gap between stacked plot tabs, in pixels.
const GAP_PX: usize = 8;
/// Colour of the gaps and of the padding right of narrower parts.
const PAD: Color32 = Color32::from_rgb(27, 27, 27);

/// Where each part of the central area was drawn this frame, in points.
#[derive(Clone, Debug, Default)]
pub struct Regions {
    /// The lab's views drawn this frame: (index in `Page::views`, rect).
    pub views: Vec<(usize, Rect)>,
    /// The plot tab row and the plot.
    pub plots: Option<Rect>,
    /// The plot alone (its axes and legend included, the tabs not).
    pub plot_area: Option<Rect>,
}

impl Regions {
    /// The rect of `target`, if it was drawn.
    pub fn of(&self, target: PngTarget) -> Option<Rect> {
        match target {
            PngTarget::View(k) => self.views.iter().find(|(i, _)| *i == k).map(|(_, r)| *r),
            PngTarget::Plots => self.plots,
        }
    }
}

/// A finished picture.
#[derive(Clone, Debug)]
pub struct Png {
    /// Encoded PNG bytes.
    pub bytes: Vec<u8>,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
}

/// Why no picture was made; [`PngError::message`] says it in the reader's language.
#[derive(Clone, Debug, PartialEq)]
pub enum PngError {
    /// The renderer gave no screenshot within this many frames (it cannot take them).
    NoPicture(u32),
    /// The part to capture was not drawn (the view was closed meanwhile).
    OffScreen,
    /// The picture has no pixels (width × height).
    Empty(usize, usize),
    /// The picture is too large for a PNG (width × height).
    TooLarge(usize, usize),
    /// The PNG encoder's own error (its words are the png crate's).
    Encoder(String),
}

impl PngError {
    /// The reason in `lang`, after "PNG export failed:".
    pub fn message(&self, lang: attlab::i18n::Lang) -> String {
        use attlab::i18n::{t, t_with};
        let size = |w: &usize, h: &usize| [("w", (*w).into()), ("h", (*h).into())];
        match self {
            Self::NoPicture(n) => t_with(lang, "png-why-no-picture", &[("n", (*n).into())]),
            Self::OffScreen => t(lang, "png-why-off-screen"),
            Self::Empty(w, h) => t_with(lang, "png-why-empty", &size(w, h)),
            Self::TooLarge(w, h) => t_with(lang, "png-why-too-large", &size(w, h)),
            Self::Encoder(e) => t_with(lang, "png-why-encoder", &[("detail", e.clone().into())]),
        }
    }
}

/// What a capture asks of the frame loop after a frame.
#[derive(Debug)]
pub enum Step {
    /// Draw another frame (a repaint has been requested).
    Continue,
    /// The capture is over.
    Done(Result<Png, PngError>),
}

/// The screenshot a request delivers, filled in by the renderer's callback.
type Slot = Arc<Mutex<Option<Arc<ColorImage>>>>;

/// One capture in progress.
pub struct Capture {
    target: PngTarget,
    /// The tabs of the lab the capture started on.
    tabs: Vec<PlotTab>,
    /// Plot tabs still to capture, next first.
    queue: std::collections::VecDeque<PlotTab>,
    /// The tab to show while capturing (None: leave it).
    showing: Option<PlotTab>,
    /// The tab the user had.
    restore: PlotTab,
    settle: u32,
    pending: Option<(Slot, u32)>,
    parts: Vec<ColorImage>,
}

impl Capture {
    /// A capture of `target`; for the plots, of every tab in `tabs`, coming back to `current`.
    pub fn new(target: PngTarget, tabs: Vec<PlotTab>, current: PlotTab) -> Self {
        let mut queue: std::collections::VecDeque<PlotTab> = match target {
            PngTarget::Plots => tabs.clone().into(),
            PngTarget::View(_) => Default::default(),
        };
        let showing = queue.pop_front();
        Self {
            target,
            tabs,
            queue,
            showing,
            restore: current,
            settle: SETTLE_FRAMES,
            pending: None,
            parts: Vec::new(),
        }
    }

    /// What is being captured.
    pub fn target(&self) -> PngTarget {
        self.target
    }

    /// The plot tabs of the lab the capture started on.
    pub fn lab_tabs(&self) -> &[PlotTab] {
        &self.tabs
    }

    /// The plot tab to draw this frame.
    pub fn tab(&self) -> PlotTab {
        self.showing.unwrap_or(self.restore)
    }

    /// The tab to return to when the capture ends.
    pub fn restore_tab(&self) -> PlotTab {
        self.restore
    }

    /// Called after each frame with where things were drawn and the scale from points to
    /// pixels: asks for a screenshot, or takes the one that arrived and moves on.
    pub fn after_frame(&mut self, ctx: &egui::Context, regions: &Regions) -> Step {
        ctx.request_repaint();
        if let Some((slot, waited)) = self.pending.as_mut() {
            let image = slot.lock().ok().and_then(|mut s| s.take());
            let Some(image) = image else {
                *waited += 1;
                if *waited > MAX_WAIT_FRAMES {
                    return Step::Done(Err(PngError::NoPicture(MAX_WAIT_FRAMES)));
                }
                return Step::Continue;
            };
            self.pending = None;
            let Some(rect) = regions.of(self.target) else {
                return Step::Done(Err(PngError::OffScreen));
            };
            self.parts.push(crop(&image, rect, ctx.pixels_per_point()));
            return match self.queue.pop_front() {
                Some(next) => {
                    self.showing = Some(next);
                    self.settle = SETTLE_FRAMES;
                    Step::Continue
                }
                None => Step::Done(encode(&stack(&self.parts))),
            };
        }
        if self.settle > 0 {
            self.settle -= 1;
            return Step::Continue;
        }
        let slot: Slot = Arc::default();
        let filled = Arc::clone(&slot);
        ctx.request_screenshot(move |image| {
            if let Ok(mut s) = filled.lock() {
                *s = Some(image);
            }
        });
        self.pending = Some((slot, 0));
        Step::Continue
    }

    /// Hands a screenshot to the request in flight, as a renderer would (tests).
    pub fn deliver(&mut self, image: ColorImage) -> bool {
        match &self.pending {
            Some((slot, _)) => slot.lock().map(|mut s| *s = Some(Arc::new(image))).is_ok(),
            None => false,
        }
    }

    /// Whether a screenshot has been asked for and not yet delivered.
    pub fn waiting(&self) -> bool {
        self.pending.is_some()
    }
}

/// The part of `image` (in pixels) under `rect` (in points), clamped to the image.
pub fn crop(image: &ColorImage, rect: Rect, pixels_per_point: f32) -> ColorImage {
    let [w, h] = image.size;
    let px = |v: f32, max: usize| ((v * pixels_per_point).round().max(0.0) as usize).min(max);
    let (x0, x1) = (px(rect.min.x, w), px(rect.max.x, w));
    let (y0, y1) = (px(rect.min.y, h), px(rect.max.y, h));
    let (cw, ch) = (x1.saturating_sub(x0), y1.saturating_sub(y0));
    let mut pixels = Vec::with_capacity(cw * ch);
    for y in y0..y0 + ch {
        pixels.extend_from_slice(&image.pixels[y * w + x0..y * w + x0 + cw]);
    }
    ColorImage::new([cw, ch], pixels)
}

/// `parts` one below the other, `GAP_PX` (8 px) apart, padded on the right to the widest.
pub fn stack(parts: &[ColorImage]) -> ColorImage {
    let width = parts.iter().map(|p| p.size[0]).max().unwrap_or(0);
    let height =
        parts.iter().map(|p| p.size[1]).sum::<usize>() + GAP_PX * parts.len().saturating_sub(1);
    let mut pixels = Vec::with_capacity(width * height);
    for (i, part) in parts.iter().enumerate() {
        if i > 0 {
            pixels.extend(std::iter::repeat_n(PAD, GAP_PX * width));
        }
        for row in part.pixels.chunks(part.size[0].max(1)) {
            pixels.extend_from_slice(row);
            pixels.extend(std::iter::repeat_n(PAD, width - row.len()));
        }
    }
    ColorImage::new([width, height], pixels)
}

/// `image` as an 8-bit RGBA PNG.
pub fn encode(image: &ColorImage) -> Result<Png, PngError> {
    let [width, height] = image.size;
    if width == 0 || height == 0 {
        return Err(PngError::Empty(width, height));
    }
    let rgba: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|c| c.to_srgba_unmultiplied())
        .collect();
    let mut bytes = Vec::new();
    {
        let too_big = |_| PngError::TooLarge(width, height);
        let mut encoder = png::Encoder::new(
            &mut bytes,
            u32::try_from(width).map_err(too_big)?,
            u32::try_from(height).map_err(too_big)?,
        );
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder
            .write_header()
            .map_err(|e| PngError::Encoder(e.to_string()))?;
        writer
            .write_image_data(&rgba)
            .map_err(|e| PngError::Encoder(e.to_string()))?;
    }
    Ok(Png {
        bytes,
        width,
        height,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{Pos2, Vec2};

    /// A 20×10 image whose pixel (x, y) has red = x and green = y.
    fn ramp() -> ColorImage {
        let pixels = (0..10u8)
            .flat_map(|y| (0..20u8).map(move |x| Color32::from_rgb(x, y, 7)))
            .collect();
        ColorImage::new([20, 10], pixels)
    }

    #[test]
    fn crop_takes_the_rect_in_pixels_and_clamps_it() {
        // 2 pixels per point: points (2, 1)–(5, 3) are pixels (4, 2)–(10, 6).
        let rect = Rect::from_min_max(Pos2::new(2.0, 1.0), Pos2::new(5.0, 3.0));
        let c = crop(&ramp(), rect, 2.0);
        assert_eq!(c.size, [6, 4]);
        assert_eq!(c.pixels[0], Color32::from_rgb(4, 2, 7));
        assert_eq!(c.pixels[6 * 4 - 1], Color32::from_rgb(9, 5, 7));
        // Past the edge: only what is on the image.
        let off = Rect::from_min_size(Pos2::new(8.0, 3.0), Vec2::new(10.0, 10.0));
        let c = crop(&ramp(), off, 2.0);
        assert_eq!(c.size, [4, 4]);
        assert_eq!(c.pixels[0], Color32::from_rgb(16, 6, 7));
    }

    #[test]
    fn stack_pads_to_the_widest_and_keeps_order() {
        let a = ColorImage::new([3, 2], vec![Color32::RED; 6]);
        let b = ColorImage::new([5, 1], vec![Color32::BLUE; 5]);
        let s = stack(&[a, b]);
        assert_eq!(s.size, [5, 2 + GAP_PX + 1]);
        assert_eq!(s.pixels[0], Color32::RED);
        assert_eq!(s.pixels[3], PAD);
        assert_eq!(s.pixels[2 * 5], PAD);
        assert_eq!(s.pixels[(2 + GAP_PX) * 5 + 4], Color32::BLUE);
    }

    #[test]
    fn encode_round_trips_through_a_png_decoder() {
        let png = encode(&ramp()).expect("encodes");
        let decoder = png::Decoder::new(std::io::Cursor::new(png.bytes));
        let mut reader = decoder.read_info().expect("a PNG");
        let mut buf = vec![
            0;
            reader
                .output_buffer_size()
                .expect("the PNG's size fits in memory")
        ];
        let info = reader.next_frame(&mut buf).expect("one frame");
        assert_eq!((info.width, info.height), (20, 10));
        let at = |x: usize, y: usize| &buf[(y * 20 + x) * 4..(y * 20 + x) * 4 + 4];
        assert_eq!(at(13, 8), &[13, 8, 7, 255]);
        let empty = encode(&ColorImage::new([0, 0], vec![])).expect_err("no pixels");
        assert_eq!(empty, PngError::Empty(0, 0));
    }

    #[test]
    fn a_plots_capture_visits_every_tab_then_restores() {
        let tabs = vec![
            PlotTab::Figure("a"),
            PlotTab::Figure("b"),
            PlotTab::Figure("c"),
        ];
        let mut cap = Capture::new(PngTarget::Plots, tabs.clone(), PlotTab::Figure("b"));
        let ctx = egui::Context::default();
        let regions = Regions {
            views: vec![],
            plots: Some(Rect::from_min_size(
                Pos2::new(0.0, 2.0),
                Vec2::new(10.0, 4.0),
            )),
            plot_area: None,
        };
        let mut seen = Vec::new();
        let mut frames = 0;
        let result = loop {
            frames += 1;
            assert!(frames < 100, "the capture never ends");
            if seen.last() != Some(&cap.tab()) {
                seen.push(cap.tab());
            }
            if cap.waiting() {
                assert!(cap.deliver(ramp()));
            }
            if let Step::Done(r) = cap.after_frame(&ctx, &regions) {
                break r;
            }
        };
        assert_eq!(seen, tabs);
        assert_eq!(cap.restore_tab(), PlotTab::Figure("b"));
        let png = result.expect("a picture");
        // Three 10×4 crops (1 pixel per point) with two gaps.
        assert_eq!((png.width, png.height), (10, 3 * 4 + 2 * GAP_PX));
    }

    #[test]
    fn a_renderer_without_screenshots_ends_the_capture_with_a_message() {
        let mut cap = Capture::new(PngTarget::View(0), vec![], PlotTab::Figure("a"));
        let ctx = egui::Context::default();
        let regions = Regions::default();
        let mut outcome = None;
        for _ in 0..(MAX_WAIT_FRAMES + SETTLE_FRAMES + 5) {
            if let Step::Done(r) = cap.after_frame(&ctx, &regions) {
                outcome = Some(r);
                break;
            }
        }
        let err = outcome.expect("gives up").expect_err("no picture");
        assert_eq!(err, PngError::NoPicture(MAX_WAIT_FRAMES));
        // In the reader's language, with the count.
        use attlab::i18n::Lang;
        let (en, ru) = (err.message(Lang::En), err.message(Lang::Ru));
        assert!(
            en.starts_with("no picture from the renderer after 120 frames"),
            "{en}"
        );
        assert!(ru.contains("120") && ru != en, "{ru}");
    }
}
