#!/usr/bin/env python3
"""CTest web.chromium: serves the built page from a loopback server, opens it with ?check in headless Chromium
(SwiftShader's WebGL 1 when there is no GPU) and waits for the page's own check (web/web_check.cpp), which the
page POSTs to /result. Prints the page's report; exits 0 only on its PASS line, 1 on FAIL, on no answer within
--timeout seconds, or when Chromium exits first. Optional: --screenshot FILE also saves a screenshot of the
page in its interactive mode (scripts/web_screenshot.sh uses it for doc/images/web.png).

Then the model check (?check-model): a generated .glb (tests/make_glb.py) served next to the page is opened by
URL and by a simulated drop, with --lights scattered lights, and rendered in every mode (the deferred ones where
the browser's WebGL 1 has draw buffers and float targets, else refused naming what it lacks); the page POSTs each
frame to /frame. Each pair (URL, drop) must be identical, and each frame must match the native renderer's
frame of the same file and options (lidr-web-native-frame, OpenGL ES 2.0 on Mesa) within the stated
tolerance: PSNR >= MIN_PSNR and at most MAX_BAD_FRACTION of the pixels more than BAD_LEVEL levels apart (the
two rasterisers and float units differ in the last bits, and an edge pixel may land on either side).
A --large-triangles model then either renders or is refused with the page's memory estimate.
Last the bench (?bench=2&width=320&height=240): the page times two frames of every mode at the query's size and
POSTs its table, which must have the size in its title and a row per mode (lidr, tiled, clustered,
forward-multipass, forward-brute) with two frames and positive times, and must stand in the page's console too."""
import argparse
import functools
import json
import struct
import urllib.parse
import zlib
import http.server
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript"}
    result = None
    result_ready = threading.Event()
    frames = {}  # (source, mode) -> (width, height, RGBA bytes, rows top first)

    def do_POST(self):
        url = urllib.parse.urlparse(self.path)
        if url.path == "/frame":
            q = urllib.parse.parse_qs(url.query)
            data = self.rfile.read(int(self.headers.get("Content-Length", "0")))
            w, h = int(q["width"][0]), int(q["height"][0])
            if len(data) != w * h * 4:
                self.send_error(400)
                return
            Handler.frames[(q["source"][0], q["mode"][0])] = (w, h, data)
            self.send_response(204)
            self.end_headers()
            return
        if url.path != "/result":
            self.send_error(404)
            return
        body = self.rfile.read(int(self.headers.get("Content-Length", "0"))).decode("utf-8", "replace")
        Handler.result = body
        Handler.result_ready.set()
        self.send_response(204)
        self.end_headers()

    def log_message(self, *args):  # quiet: the report is what matters
        pass


def chromium_command(chromium, profile, extra):
    # As root Chromium needs --no-sandbox; the closed network refuses its background connections, so they are
    # switched off; --disable-gpu leaves WebGL to SwiftShader (software), the same on every machine.
    return [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--enable-unsafe-swiftshader", "--use-angle=swiftshader", f"--user-data-dir={profile}",
            "--enable-logging=stderr", "--v=0"] + extra


def read_png(path):
    """RGBA8 rows top first from an 8-bit RGB or RGBA, non-interlaced PNG (what lidr's writePng writes)."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs are read here")
            channels = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, out, prev = zlib.decompress(idat), width * channels, bytearray(), bytearray(width * channels)
    for y in range(height):
        kind, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1: row[i] = (row[i] + a) & 255
            elif kind == 2: row[i] = (row[i] + b) & 255
            elif kind == 3: row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = row
        if channels == 4:
            out += row
        else:
            for x in range(width):
                out += row[3 * x:3 * x + 3] + b"\xff"
    return width, height, bytes(out)


def write_png(path, width, height, rgba):
    raw = b"".join(b"\x00" + rgba[y * width * 4:(y + 1) * width * 4] for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def compare(a, b, bad_level):
    """Max channel difference (RGB), PSNR (dB, RGB) and the fraction of pixels with a channel > bad_level apart."""
    worst, squares, bad = 0, 0, 0
    for i in range(0, len(a), 4):
        d = max(abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2]))
        squares += (a[i] - b[i]) ** 2 + (a[i + 1] - b[i + 1]) ** 2 + (a[i + 2] - b[i + 2]) ** 2
        worst = max(worst, d)
        bad += d > bad_level
    pixels = len(a) // 4
    mse = squares / (3 * pixels)
    import math
    return worst, (999.0 if mse == 0 else 10 * math.log10(255 * 255 / mse)), bad / pixels


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--chromium", required=True)
    parser.add_argument("--page-dir", required=True)
    parser.add_argument("--page", default="lidr_web.html")
    parser.add_argument("--timeout", type=float, default=480.0)
    parser.add_argument("--screenshot", help="also save a screenshot of the interactive page here")
    parser.add_argument("--native-frame-tool", help="lidr-web-native-frame of a native build (the model check)")
    parser.add_argument("--model-out", help="folder for the model check's model and frames")
    parser.add_argument("--lights", type=int, default=256)
    parser.add_argument("--large-triangles", type=int, default=1000000)
    parser.add_argument("--min-psnr", type=float, default=40.0)
    parser.add_argument("--bad-level", type=int, default=8)
    parser.add_argument("--max-bad-fraction", type=float, default=0.005)
    args = parser.parse_args()

    page = os.path.join(args.page_dir, args.page)
    if not os.path.isfile(page):
        print(f"web.chromium: {page} not found: build the page first (bash scripts/setup.sh web)", file=sys.stderr)
        return 1
    model_check = bool(args.native_frame_tool)
    if model_check and not os.access(args.native_frame_tool, os.X_OK):
        print(f"web.chromium: FAIL: {args.native_frame_tool} not found: the model check compares the page with the "
              "native renderer; build it in a native build first (cmake --build build --target "
              "lidr-web-native-frame; scripts/setup.sh web does)", file=sys.stderr)
        return 1
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Handler, directory=args.page_dir))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_address[1]}/{args.page}"
    try:
        ok = run_room_check(args, url)
        if ok and model_check:
            ok = run_model_check(args, url)
        if ok:
            ok = run_bench_check(args, url)
    finally:
        server.shutdown()
    return 0 if ok else 1


def run_page(args, query, profile_name, console_lines=None):
    """Opens url+query in headless Chromium until the page POSTs /result; returns (result or None, seconds, log).
    console_lines(result) names lines the page also printed to its console: Chromium writes the console to its log
    from another process, after the POST may have arrived, so the log is read until they are there (10 s at most)."""
    Handler.result = None
    Handler.result_ready.clear()
    # Chromium's helper processes may still write into the profile while they exit: cleanup errors are ignored.
    with tempfile.TemporaryDirectory(prefix="lidr-web-chromium-", ignore_cleanup_errors=True) as profile:
        log_path = os.path.join(profile, "chromium.log")
        with open(log_path, "w") as log:
            start = time.monotonic()
            browser = subprocess.Popen(chromium_command(args.chromium, os.path.join(profile, profile_name),
                                                        [query]),
                                       stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
            try:
                while not Handler.result_ready.wait(0.5):
                    if browser.poll() is not None:
                        break
                    if time.monotonic() - start > args.timeout:
                        break
                if Handler.result is not None and console_lines is not None:
                    wanted, waited = console_lines(Handler.result), time.monotonic()
                    while time.monotonic() - waited < 10.0:
                        log.flush()
                        with open(log_path, errors="replace") as so_far:
                            text = so_far.read()
                        if all(line in text for line in wanted):
                            break
                        time.sleep(0.2)
            finally:
                # The whole process group: the browser and its renderer, GPU and utility processes.
                try:
                    os.killpg(browser.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                browser.wait()
        elapsed = time.monotonic() - start
        with open(log_path, errors="replace") as log:
            text = log.read()
        if Handler.result is None:
            why = "Chromium exited" if elapsed <= args.timeout else "timed out"
            print(f"web.chromium: FAIL: no result from the page after {elapsed:.0f} s ({why}); Chromium's log:\n"
                  f"{text[-4000:]}", file=sys.stderr)
        return Handler.result, elapsed, text


def run_room_check(args, url):
    result, elapsed, log = run_page(args, url + "?check", "profile")
    if result is None:
        return False
    print(result)
    print(f"web.chromium: the page answered after {elapsed:.1f} s (Chromium start, wasm load, check)")
    if args.screenshot:
        with tempfile.TemporaryDirectory(prefix="lidr-web-shot-", ignore_cleanup_errors=True) as profile:
            shot = subprocess.run(chromium_command(args.chromium, os.path.join(profile, "profile-shot"),
                                                   ["--window-size=1120,620", "--virtual-time-budget=20000",
                                                    f"--screenshot={os.path.abspath(args.screenshot)}", url]),
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=args.timeout)
        print(f"web.chromium: screenshot {args.screenshot} (exit {shot.returncode})")
    last = result.strip().splitlines()[-1] if result.strip() else ""
    if not last.startswith("PASS"):
        print("web.chromium: Chromium's log (the page's console):\n" + log[-6000:], file=sys.stderr)
        return False
    return True


def run_model_check(args, url):
    out = os.path.abspath(args.model_out or os.path.join(args.page_dir, "model-check"))
    models = os.path.join(args.page_dir, "models")  # served next to the page
    os.makedirs(out, exist_ok=True)
    os.makedirs(models, exist_ok=True)
    make_glb = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "make_glb.py")
    # with its own KHR_lights_punctual lights (candela, inverse square, one without range) under the scattered ones
    subprocess.run([sys.executable, make_glb, os.path.join(models, "check.glb"), "--punctual"], check=True)
    # A .gltf whose one triangle list claims 400 M vertices (its buffer is never written): refused by estimate.
    with open(os.path.join(models, "huge.gltf"), "w") as f:
        json.dump({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 400000000, "type": "VEC3",
                                  "min": [0, 0, 0], "max": [1, 1, 1]}],
                   "bufferViews": [{"buffer": 0, "byteLength": 4800000000}],
                   "buffers": [{"uri": "huge.bin", "byteLength": 4800000000}]}, f)
    query = f"?check-model=models/check.glb&lights={args.lights}&check-huge=models/huge.gltf"
    if args.large_triangles > 0:
        subprocess.run([sys.executable, make_glb, os.path.join(models, "large.glb"),
                        "--triangles", str(args.large_triangles)], check=True)
        query += "&check-large=models/large.glb"
    Handler.frames.clear()
    result, elapsed, log = run_page(args, url + query, "profile-model")
    if result is None:
        return False
    print(result)
    print(f"web.chromium: the model check answered after {elapsed:.1f} s")
    if not result.strip().endswith("FRAMES: the runner compares them"):
        print("web.chromium: FAIL: the model check did not finish; Chromium's log:\n" + log[-6000:], file=sys.stderr)
        return False
    ok = True
    env = dict(os.environ, MESA_GLES_VERSION_OVERRIDE="2.0")  # a true ES 2.0, as WebGL 1 is
    for mode in BENCH_MODES + DEFERRED_MODES:
        refusal = next((line for line in result.splitlines() if line.startswith(f"url {mode}: refused:")), None)
        if mode in DEFERRED_MODES and refusal and ("url", mode) not in Handler.frames:
            named = any(need in refusal for need in DEFERRED_NEEDS)
            ok = ok and named
            print(f"{'ok  ' if named else 'FAIL'} {mode}: refused by this WebGL 1"
                  f"{'' if named else ' without naming what it lacks'}: {refusal}")
            continue
        if ("url", mode) not in Handler.frames or ("drop", mode) not in Handler.frames:
            print(f"FAIL {mode}: the page sent no frame by URL and by drop")
            ok = False
            continue
        w, h, by_url = Handler.frames[("url", mode)]
        by_drop = Handler.frames[("drop", mode)][2]
        write_png(os.path.join(out, f"page-{mode}.png"), w, h, by_url)
        native_png = os.path.join(out, f"native-{mode}.png")
        native = subprocess.run([args.native_frame_tool, os.path.join(models, "check.glb"), str(args.lights), mode,
                                 str(w), str(h), native_png], env=env, capture_output=True, text=True)
        if native.returncode != 0:
            print(f"FAIL {mode}: lidr-web-native-frame: {native.stderr.strip()}")
            ok = False
            continue
        nw, nh, native_rgba = read_png(native_png)
        same = by_url == by_drop
        worst, psnr, bad = compare(by_url, native_rgba, args.bad_level) if (nw, nh) == (w, h) else (255, 0.0, 1.0)
        lit = sum(1 for i in range(0, len(by_url), 4) if by_url[i] + by_url[i + 1] + by_url[i + 2] > 60) / (w * h)
        passed = same and psnr >= args.min_psnr and bad <= args.max_bad_fraction and lit > 0.03
        ok = ok and passed
        print(f"{'ok  ' if passed else 'FAIL'} {mode} {w}x{h}, {args.lights} lights: by URL and by drop "
              f"{'identical' if same else 'DIFFERENT'}; against the native frame: max error {worst}, PSNR "
              f"{psnr:.1f} dB, {100 * bad:.3f}% of pixels more than {args.bad_level} levels apart "
              f"(bounds: PSNR >= {args.min_psnr}, <= {100 * args.max_bad_fraction}%); {100 * lit:.1f}% lit")
    print(("PASS" if ok else "FAIL") + f": the model by URL and by drop against the native frames ({out})")
    return ok


BENCH_MODES = ("lidr", "tiled", "clustered", "forward-multipass", "forward-brute")
BENCH_ROWS = [[mode] for mode in BENCH_MODES]  # a row's first word
# The deferred modes' RGBA16F G-buffer needs WEBGL_draw_buffers and half-float colour targets; without them the
# default G-buffer is RGBA8 (doc/deferred.md). Timed where the mode runs, else a row that says refused, naming what
# is missing.
DEFERRED_MODES = ("deferred", "tiled-deferred")
DEFERRED_NEEDS = ("draw_buffers", "float", "half")


def run_bench_check(args, url):
    def bench_rows(result):
        return [line.strip() for line in result.strip().splitlines()[2:] if line.split()[:1] in BENCH_ROWS]
    result, elapsed, log = run_page(args, url + "?bench=2&width=320&height=240", "profile-bench", bench_rows)
    if result is None:
        return False
    print(result.rstrip())
    print(f"web.chromium: the bench answered after {elapsed:.1f} s")
    lines = result.strip().splitlines()
    problems = []
    if not lines or not lines[0].startswith("lidr-web bench: 2 frames per mode") or "320x240" not in lines[0]:
        problems.append("the title does not name 2 frames per mode at 320x240")
    for mode in BENCH_MODES:
        rows = [line for line in lines[2:] if line.split()[:1] == [mode]]
        if len(rows) != 1:
            problems.append(f"{len(rows)} rows for mode {mode}, not 1")
            continue
        fields = rows[0].split()
        try:
            figures = [float(x) for x in fields[2:7]]
        except ValueError:
            figures = []
        if fields[1:2] != ["2"] or len(figures) != 5 or min(figures) <= 0.0:
            problems.append(f"mode {mode}: not 2 frames with positive times: {rows[0]!r}")
        elif rows[0].strip() not in log:  # the page printed the table to the console (Chromium's log)
            problems.append(f"mode {mode}: its row is not in the page's console")
    for mode in DEFERRED_MODES:
        rows = [line for line in lines[2:] if line.split()[:1] == [mode]]
        if len(rows) != 1:
            problems.append(f"{len(rows)} rows for mode {mode}, not 1")
            continue
        fields = rows[0].split()
        if fields[1:2] == ["refused:"]:
            if not any(need in rows[0] for need in DEFERRED_NEEDS):
                problems.append(f"mode {mode}: refused without naming what WebGL 1 lacks: {rows[0]!r}")
            continue
        try:
            figures = [float(x) for x in fields[2:7]]
        except ValueError:
            figures = []
        if fields[1:2] != ["2"] or len(figures) != 5 or min(figures) <= 0.0:
            problems.append(f"mode {mode}: neither 2 frames with positive times nor refused: {rows[0]!r}")
    for problem in problems:
        print(f"FAIL bench: {problem}")
    if problems:
        print("web.chromium: Chromium's log (the page's console):\n" + log[-6000:], file=sys.stderr)
    print(("PASS" if not problems else "FAIL") + ": the bench table, a row per mode, shown and printed")
    return not problems


if __name__ == "__main__":
    sys.exit(main())
