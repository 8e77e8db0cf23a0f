#!/usr/bin/env python3
"""Regenerates the app's two fonts (assets/fonts/*.ttf) as subsets of egui's.

egui bundles Ubuntu Light (text) and Hack (monospace) whole: 660 KB, about a
tenth of the gzipped download. Shoal keeps the scripts its catalogue and a
class's typing use (Latin with every accent, Greek for the equations, arrows,
maths and punctuation) and every character in its sources, so nothing it shows
changes; the hinting stays, so text is drawn as before. Cyrillic and the rest
are left out (add a range below when a language needs it).

    python3 -m venv /tmp/fonts && /tmp/fonts/bin/pip install fonttools==4.68.0
    /tmp/fonts/bin/python assets/fonts/subset.py ~/.cargo/registry/src/*/epaint_default_fonts-0.37.0/fonts

The Ubuntu Font Licence asks a modified font to keep its name with
"derivative <name>" appended, which this script writes into the name table.
"""
import glob
import os
import sys

from fontTools import subset
from fontTools.ttLib import TTFont

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Latin (all accents, Vietnamese), IPA and modifiers, combining marks, Greek,
# punctuation, super- and subscripts, currency, letter-like symbols, number
# forms, arrows, maths, technical symbols, shapes, symbols, replacement char.
TEXT_RANGES = [
    (0x20, 0x7E), (0xA0, 0x24F), (0x250, 0x36F), (0x370, 0x3FF), (0x1E00, 0x1EFF),
    (0x2000, 0x218F), (0x2190, 0x23FF), (0x25A0, 0x26FF), (0x2C60, 0x2C7F),
    (0xA720, 0xA7FF), (0xFFFD, 0xFFFD),
]
# Monospace shows numbers, values and links (and the sources' symbols); anything
# else falls back to the text font.
MONO_RANGES = [(0x20, 0x7E), (0xA0, 0xFF), (0xFFFD, 0xFFFD)]
MONO_EXTRA = "–—…−≈≤≥±×÷°"


def used_characters():
    """Every non-ASCII character in the catalogue and the Rust sources."""
    found = set()
    paths = glob.glob(os.path.join(ROOT, "locales", "*", "*.ftl"))
    paths += glob.glob(os.path.join(ROOT, "src", "**", "*.rs"), recursive=True)
    for path in paths:
        with open(path, encoding="utf-8") as f:
            found |= {ord(ch) for ch in f.read() if ord(ch) > 0x7E}
    return found


def codepoints(ranges, extra=()):
    cps = set(extra)
    for lo, hi in ranges:
        cps |= set(range(lo, hi + 1))
    return cps


def make(source, target, cps, derivative_name):
    font = TTFont(source)
    options = subset.Options()
    options.layout_features = ["*"]
    options.name_IDs = ["*"]
    options.notdef_outline = True
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=sorted(cps & set(font.getBestCmap())))
    subsetter.subset(font)
    if derivative_name:
        names = font["name"]
        for record in names.names:
            if record.nameID in (1, 3, 4, 6, 16, 17):
                text = record.toUnicode()
                suffix = " derivative Shoal" if record.nameID != 6 else "-derivative-Shoal"
                record.string = text + suffix
    font.save(target)
    print(f"{os.path.basename(target)}: {os.path.getsize(target)} bytes")


def main():
    fonts = sys.argv[1] if len(sys.argv) > 1 else None
    if not fonts:
        sys.exit("usage: subset.py <epaint_default_fonts>/fonts")
    make(
        os.path.join(fonts, "Ubuntu-Light.ttf"),
        os.path.join(HERE, "Ubuntu-Light-subset.ttf"),
        codepoints(TEXT_RANGES) | used_characters(),
        derivative_name=True,
    )
    make(
        os.path.join(fonts, "Hack-Regular.ttf"),
        os.path.join(HERE, "Hack-Regular-subset.ttf"),
        codepoints(MONO_RANGES, (ord(c) for c in MONO_EXTRA)) | used_characters(),
        derivative_name=False,
    )


if __name__ == "__main__":
    main()
