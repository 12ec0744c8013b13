#!/usr/bin/env python3
"""Regenerates the app's three subset fonts (run from anywhere; needs fonttools).

The page ships these instead of egui's bundled fonts (eframe's `default_fonts` feature is off):
the whole Ubuntu-Light and Hack files are 0.67 MB of the wasm, and the app draws only Latin,
Greek, Cyrillic, punctuation and a few symbols.

- AttLabSans.ttf  <- Ubuntu-Light (egui's proportional font; Ubuntu Font Licence, UFL.txt)
- AttLabMono.ttf  <- Hack-Regular (egui's monospace font; MIT + Bitstream Vera, Hack-Regular.txt)
- DejaVuSans-symbols.ttf <- DejaVu Sans: what Ubuntu-Light lacks — combining accents (φ̇, φ̂;
  also copied into the two subsets above, see `add_marks`),
  ϑ, modifier letters (ᵀ, ᵃ), primes, super/subscripts, arrows, maths and a few UI symbols
  (Bitstream Vera licence, LICENSE-DejaVu.txt; Debian's fonts-dejavu-core).

Both licences of the first two ask a modified font not to keep the reserved names, so the
subsets are renamed. The test `every_label_has_a_glyph` (web/src/render/fonts.rs) fails when a
label in the source uses a character none of the three has.
"""
import glob
import os
from fontTools import subset
from fontTools.pens.recordingPen import DecomposingRecordingPen
from fontTools.pens.transformPen import TransformPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import TTFont

DEJAVU = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

HERE = os.path.dirname(os.path.abspath(__file__))
REGISTRY = os.environ.get("EPAINT_FONTS", os.path.expanduser("~/.cargo/registry/src/*/epaint_default_fonts-0.37.0/fonts"))

# Latin (ASCII, Latin-1, Latin Extended-A), Greek, Cyrillic (the page speaks Russian; +11 kB
# gzipped for both fonts), the numero sign, general punctuation, super/subscripts,
# the euro sign and letter-like symbols. Monospace falls back to the other two for the rest.
TEXT = "U+0020-007E,U+00A0-017F,U+0370-03FF,U+0400-045F,U+2116,U+2000-206F,U+2070-209F,U+20AC,U+2100-214F,U+FFFD"
MONO = TEXT
SYMBOLS = ("U+0300-036F,U+03D0-03FF,U+1D2C-1D6A,U+2032-2037,U+2070-209F,U+2190-21FF,"
           "U+2200-22FF,U+25B6,U+25C0,U+25CF,U+2715,U+27F2-27F3")


def cut(src, unicodes, out, family=None):
    font = TTFont(src)
    options = subset.Options()
    options.hinting = False
    options.desubroutinize = True
    options.drop_tables += ["FFTM"]
    options.layout_features = ["kern", "liga", "mark", "mkmk", "ccmp", "locl"]
    sub = subset.Subsetter(options)
    sub.populate(unicodes=subset.parse_unicodes(unicodes))
    sub.subset(font)
    if family:
        for rec in font["name"].names:
            if rec.nameID in (1, 4, 16):
                rec.string = family
            elif rec.nameID == 6:
                rec.string = family.replace(" ", "")
    font.save(os.path.join(HERE, out))
    print(f"{out}: {os.path.getsize(os.path.join(HERE, out))} bytes")


def add_marks(out):
    """Copies DejaVu Sans's combining marks (U+0300-036F) into the subset `out`, scaled to its
    em. egui shapes a run per font, so a mark from the fallback font after a letter of this one
    was dropped: φ̇, θ̂ and x̂ showed as φ, θ and x. DejaVu's marks have no advance and sit over
    the glyph before them, so without anchors they still land above the letter."""
    path = os.path.join(HERE, out)
    font, dejavu = TTFont(path), TTFont(DEJAVU)
    scale = font["head"].unitsPerEm / dejavu["head"].unitsPerEm
    source, glyphs, have = dejavu.getBestCmap(), dejavu.getGlyphSet(), font.getBestCmap()
    added = []
    for cp in range(0x300, 0x370):
        if cp in have or cp not in source:
            continue
        name, new = source[cp], "uni%04X" % cp
        recording, pen = DecomposingRecordingPen(glyphs), TTGlyphPen(None)
        glyphs[source[cp]].draw(recording)
        recording.replay(TransformPen(pen, (scale, 0, 0, scale, 0, 0)))
        font["glyf"][new] = glyph = pen.glyph()
        glyph.recalcBounds(font["glyf"])
        advance = dejavu["hmtx"][name][0]
        font["hmtx"][new] = (round(advance * scale), getattr(glyph, "xMin", 0))
        for table in font["cmap"].tables:
            if table.isUnicode():
                table.cmap[cp] = new
        added.append(new)
    order = font.getGlyphOrder()
    font.setGlyphOrder(order + [g for g in added if g not in order])
    font["maxp"].numGlyphs = len(font.getGlyphOrder())
    font.save(path)
    print(f"{out}: {len(added)} combining marks added, {os.path.getsize(path)} bytes")


def registry_font(name):
    found = glob.glob(os.path.join(REGISTRY, name))
    if not found:
        raise SystemExit(f"{name} not found under {REGISTRY}: run `cargo fetch` first")
    return found[0]


cut(registry_font("Ubuntu-Light.ttf"), TEXT, "AttLabSans.ttf", "AttLab Sans")
cut(registry_font("Hack-Regular.ttf"), MONO, "AttLabMono.ttf", "AttLab Mono")
cut(DEJAVU, SYMBOLS, "DejaVuSans-symbols.ttf")
add_marks("AttLabSans.ttf")
add_marks("AttLabMono.ttf")
