#!/usr/bin/env python3
"""Renders one glTF model in lidr and in three.js with the same camera, the same environment light and the same
output transform, and writes both images, their difference and the figures (issue 39, part 5; doc/colour.md,
"Beside three.js").

  python3 scripts/threejs_compare.py MODEL.glb [--out DIR] [--width W --height H] [--environment default|FILE.hdr]

- three.js comes from the npm registry at a pinned version (--three-version), installed with npm into a temporary
  folder that is removed afterwards: never committed, never fetched at build time.
- lidr: lidr-demo --headless --mode forward-brute --no-default-lights (the environment alone lights the model, as
  in three.js), the environment written out as an equirectangular .hdr (--export-environment) so that three.js
  loads the very same radiance through RGBELoader and prefilters it with its PMREMGenerator.
- three.js: MeshStandardMaterial from GLTFLoader, scene.environment, NeutralToneMapping (Khronos PBR Neutral,
  lidr's default tone map), sRGB output, lidr's camera (summary.json), no light; in headless Chromium
  (SwiftShader's WebGL 2, the flags web/run_chromium_check.py uses), the pixels POSTed to a loopback server.
- Writes lidr.png, threejs.png, difference.png (|lidr - three.js| x 4), side_by_side.png (the three in a row) and
  compare.json (PSNR and max error over
  the whole image and over the model's pixels, the mean signed difference per channel) into --out.
Python's standard library, npm and Chromium only."""
import argparse
import http.server
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import urllib.parse

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "web"))
from run_chromium_check import chromium_command, read_png, write_png  # noqa: E402


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".js": "text/javascript",
                      ".hdr": "application/octet-stream"}
    frame = None
    result = None
    done = threading.Event()

    def do_POST(self):
        url = urllib.parse.urlparse(self.path)
        body = self.rfile.read(int(self.headers.get("Content-Length", "0")))
        if url.path == "/frame":
            q = urllib.parse.parse_qs(url.query)
            Handler.frame = (int(q["width"][0]), int(q["height"][0]), body)
        elif url.path == "/result":
            Handler.result = body.decode("utf-8", "replace")
            Handler.done.set()
        self.send_response(204)
        self.end_headers()

    def log_message(self, *args):
        pass


def figures(a, b, mask):
    """PSNR (peak 255), max error and mean signed difference (a - b) per channel over the masked pixels."""
    sq, worst, n, signed = 0.0, 0, 0, [0.0, 0.0, 0.0]
    for p in range(len(mask)):
        if not mask[p]:
            continue
        n += 1
        for k in range(3):
            d = a[4 * p + k] - b[4 * p + k]
            sq += d * d
            worst = max(worst, abs(d))
            signed[k] += d
    if n == 0:
        return {"pixels": 0}
    mse = sq / (3 * n)
    return {"pixels": n, "psnr_db": round(999.0 if mse == 0 else 10 * math.log10(255 * 255 / mse), 2),
            "max_error": worst, "mean_signed_difference_rgb": [round(s / n, 2) for s in signed]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("model")
    ap.add_argument("--out", default="threejs-compare-out")
    ap.add_argument("--width", type=int, default=512)
    ap.add_argument("--height", type=int, default=384)
    ap.add_argument("--environment", default="default", help="default (lidr's studio room) or an .hdr panorama")
    ap.add_argument("--three-version", default="0.169.0")
    ap.add_argument("--lidr-demo", default="build/demo/lidr-demo")
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--timeout", type=float, default=600.0)
    args = ap.parse_args()
    for tool in (args.lidr_demo, args.chromium):
        if not os.access(tool, os.X_OK):
            sys.exit(f"threejs_compare: {tool} not found (build lidr-demo: cmake --build build --target lidr-demo)")
    os.makedirs(args.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="lidr-threejs-")
    try:
        print(f"threejs_compare: npm install three@{args.three_version} into {work}")
        subprocess.run(["npm", "install", "--prefix", work, "--no-audit", "--no-fund", "--loglevel=error",
                        f"three@{args.three_version}"], check=True)
        lidr_out = os.path.join(work, "lidr")
        env_hdr = os.path.join(work, "env.hdr")
        command = [args.lidr_demo, "--headless", "--scene", args.model, "--mode", "forward-brute", "--no-default-lights",
                   "--width", str(args.width), "--height", str(args.height), "--environment", args.environment,
                   "--export-environment", env_hdr, "--frames", "1", "--no-reference", "--out", lidr_out]
        print("threejs_compare: " + " ".join(command))
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(lidr_out, "summary.json")) as f:
            summary = json.load(f)
        camera = summary["scene"]["camera"]
        shutil.copy(args.model, os.path.join(work, "model.glb"))
        shutil.copy(os.path.join(os.path.dirname(os.path.abspath(__file__)), "threejs_compare.html"),
                    os.path.join(work, "index.html"))
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), lambda *a, **k: Handler(*a, directory=work, **k))
        threading.Thread(target=server.serve_forever, daemon=True).start()
        url = (f"http://127.0.0.1:{server.server_port}/index.html?width={args.width}&height={args.height}"
               f"&camera={urllib.parse.quote(json.dumps(camera))}")
        profile = os.path.join(work, "profile")
        browser = subprocess.Popen(chromium_command(args.chromium, profile, [url]),
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            if not Handler.done.wait(args.timeout):
                sys.exit(f"threejs_compare: no answer from the page within {args.timeout} s")
        finally:
            browser.kill()
            browser.wait()
            server.shutdown()
        if not Handler.result.startswith("OK") or Handler.frame is None:
            sys.exit("threejs_compare: the page: " + Handler.result)
        w, h, three = Handler.frame
        lw, lh, lidr = read_png(os.path.join(lidr_out, "forward-brute.png"))
        if (lw, lh) != (w, h):
            sys.exit(f"threejs_compare: lidr wrote {lw}x{lh}, three.js {w}x{h}")
        write_png(os.path.join(args.out, "lidr.png"), w, h, lidr)
        write_png(os.path.join(args.out, "threejs.png"), w, h, three)
        diff = bytearray(len(lidr))
        for i in range(0, len(lidr), 4):
            for k in range(3):
                diff[i + k] = min(255, 4 * abs(lidr[i + k] - three[i + k]))
            diff[i + 3] = 255
        write_png(os.path.join(args.out, "difference.png"), w, h, bytes(diff))
        row = w * 4  # lidr | three.js | difference, one image for the docs
        both = b"".join(lidr[y * row:(y + 1) * row] + three[y * row:(y + 1) * row] + bytes(diff[y * row:(y + 1) * row])
                        for y in range(h))
        write_png(os.path.join(args.out, "side_by_side.png"), 3 * w, h, both)
        everything = [True] * (w * h)
        model = [any(lidr[4 * p + k] or three[4 * p + k] for k in range(3)) for p in range(w * h)]
        result = {"model": args.model, "width": w, "height": h, "environment": args.environment,
                  "three": Handler.result[3:], "lidr": summary["environment"]["description"], "camera": camera,
                  "whole_image": figures(lidr, three, everything), "model_pixels": figures(lidr, three, model)}
        with open(os.path.join(args.out, "compare.json"), "w") as f:
            json.dump(result, f, indent=2)
        print(json.dumps(result, indent=2))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
