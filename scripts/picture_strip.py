#!/usr/bin/python3
"""Lays equally sized pictures side by side, each under its label, into one PNG.

    picture_strip.py OUT.png "label one=a.png" "label two=b.png" ...

Grey and colour inputs may be mixed; every input must have the size of the
first. Used by scripts/make-pictures.sh for the README's opening picture.
Needs Debian's python3-pil (and fonts-dejavu-core for the labels' font).
"""
import sys

from PIL import Image, ImageDraw, ImageFont

GAP = 6            # pixels between panels
LABEL_HEIGHT = 30  # the band above each panel
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def font(size):
    try:
        return ImageFont.truetype(FONT, size)
    except OSError:
        return ImageFont.load_default()


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[2:]):
        sys.exit("usage: picture_strip.py OUT.png 'label=picture.png' ...")
    out = argv[1]
    panels = []
    for arg in argv[2:]:
        label, path = arg.rsplit("=", 1)
        try:
            panels.append((label, Image.open(path).convert("RGB")))
        except OSError as e:
            sys.exit(f"picture_strip.py: cannot read {path}: {e}")
    w, h = panels[0][1].size
    for label, image in panels:
        if image.size != (w, h):
            sys.exit(f"picture_strip.py: '{label}' is {image.size[0]}x{image.size[1]}, the first picture {w}x{h}")
    sheet = Image.new("RGB", (len(panels) * w + (len(panels) - 1) * GAP, LABEL_HEIGHT + h), "white")
    draw = ImageDraw.Draw(sheet)
    f = font(18)
    for i, (label, image) in enumerate(panels):
        x = i * (w + GAP)
        sheet.paste(image, (x, LABEL_HEIGHT))
        left, top, right, bottom = draw.textbbox((0, 0), label, font=f)
        draw.text((x + (w - (right - left)) / 2, (LABEL_HEIGHT - (bottom - top)) / 2 - top), label, fill="black", font=f)
    sheet.save(out, optimize=True)


if __name__ == "__main__":
    main(sys.argv)
