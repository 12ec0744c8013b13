#!/usr/bin/env bash
# Regenerates DejaVuSans-symbols.ttf: the glyphs the app's labels use that egui's default
# font (Ubuntu-Light) lacks — combining accents (φ̇, φ̂), ϑ, modifier letters (ᵀ, ᵃ),
# primes, super/subscripts, arrows, math operators and a few UI symbols — cut from DejaVu
# Sans (Bitstream Vera licence, LICENSE-DejaVu.txt). Needs fonttools (pip install fonttools)
# and Debian's fonts-dejavu-core.
set -euo pipefail
cd "$(dirname "$0")"
pyftsubset /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf \
  --unicodes="U+0300-036F,U+03D0-03FF,U+1D2C-1D6A,U+2032-2037,U+2070-209F,U+2190-21FF,U+2200-22FF,U+25B6,U+25C0,U+25CF,U+2715,U+27F2-27F3" \
  --output-file=DejaVuSans-symbols.ttf --no-hinting --desubroutinize --drop-tables+=FFTM
