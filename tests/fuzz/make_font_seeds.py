#!/usr/bin/python3
"""Writes the font fuzzer's seeds, corpus/font/tiny.ttf and tiny.otf: two
small fonts drawn here (fontTools' FontBuilder, Debian's python3-fonttools),
so that the seeds are ours. Glyphs: .notdef (a box), O (a ring: TrueType
quadratics with implied on-curve points, or CFF cubics), 8 (two contours),
space; a kerning pair would need GPOS/kern and is left to the fuzzer.
Run from this folder: /usr/bin/python3 make_font_seeds.py"""
from fontTools.fontBuilder import FontBuilder
from fontTools.pens.t2CharStringPen import T2CharStringPen
from fontTools.pens.ttGlyphPen import TTGlyphPen

ORDER = [".notdef", "space", "O", "eight"]
CMAP = {0x20: "space", ord("O"): "O", ord("8"): "eight"}
ADVANCES = {".notdef": 500, "space": 250, "O": 700, "eight": 560}


def draw(pen, name, cubic):
    if name == ".notdef":
        for box in ([(50, 0), (450, 0), (450, 700), (50, 700)], [(100, 50), (100, 650), (400, 650), (400, 50)]):
            pen.moveTo(box[0])
            for p in box[1:]:
                pen.lineTo(p)
            pen.closePath()
    elif name in ("O", "eight"):
        rings = [(350, 350, 300, 340), (350, 350, 200, 240)] if name == "O" else \
                [(280, 190, 220, 190), (280, 540, 180, 160)]
        for k, (cx, cy, rx, ry) in enumerate(rings):
            # A closed curve through four points; reversed for the inner ring (a hole).
            points = [(cx + rx, cy), (cx, cy + ry), (cx - rx, cy), (cx, cy - ry)]
            if k == 1 and name == "O":
                points.reverse()
            pen.moveTo(points[0])
            for i in range(4):
                a, b = points[i], points[(i + 1) % 4]
                corner = (a[0] if a[1] == cy else b[0], a[1] if a[1] != cy else b[1])
                if cubic:
                    pen.curveTo(((a[0] + 2 * corner[0]) / 3, (a[1] + 2 * corner[1]) / 3),
                                ((b[0] + 2 * corner[0]) / 3, (b[1] + 2 * corner[1]) / 3), b)
                else:
                    pen.qCurveTo(corner, b)
            pen.closePath()


def build(cubic, path):
    fb = FontBuilder(1000, isTTF=not cubic)
    fb.setupGlyphOrder(ORDER)
    fb.setupCharacterMap(CMAP)
    metrics = {name: (ADVANCES[name], 0) for name in ORDER}
    if cubic:
        charstrings = {}
        for name in ORDER:
            pen = T2CharStringPen(ADVANCES[name], None)
            draw(pen, name, True)
            charstrings[name] = pen.getCharString()
        fb.setupCFF("casteljauFuzzSeed", {"FullName": "casteljau fuzz seed"}, charstrings, {})
    else:
        glyphs = {}
        for name in ORDER:
            pen = TTGlyphPen(None)
            draw(pen, name, False)
            glyphs[name] = pen.glyph()
        fb.setupGlyf(glyphs)
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "casteljau fuzz seed", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    fb.save(path)


build(False, "corpus/font/tiny.ttf")
build(True, "corpus/font/tiny.otf")
