#!/usr/bin/env python3
"""How much of a model reads near-black: the pixels of MASK.png that are not the background (any channel above
0) are the model's; prints, as JSON, their count and the share of them whose brightest channel is below
--level (default 32 of 255, about 1.5 % linear after sRGB) in each IMAGE.png (demo.headless: the metal showcase
with and without the environment light, issue 39).

    python3 tests/dark_pixels.py MASK.png IMAGE.png [IMAGE.png ...] [--level N]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "web"))
from run_chromium_check import read_png  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mask")
    ap.add_argument("images", nargs="+")
    ap.add_argument("--level", type=int, default=32)
    args = ap.parse_args()
    w, h, mask = read_png(args.mask)
    model = [p for p in range(w * h) if any(mask[4 * p + k] for k in range(3))]
    result = {"model_pixels": len(model), "dark_share": {}}
    for path in args.images:
        iw, ih, image = read_png(path)
        if (iw, ih) != (w, h):
            sys.exit(f"{path}: {iw}x{ih}, the mask is {w}x{h}")
        dark = sum(1 for p in model if max(image[4 * p:4 * p + 3]) < args.level)
        result["dark_share"][os.path.basename(os.path.dirname(path)) + "/" + os.path.basename(path)] = \
            round(dark / max(1, len(model)), 4)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
