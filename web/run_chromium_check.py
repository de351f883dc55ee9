#!/usr/bin/env python3
"""CTest web.chromium: serves the built page from a loopback server, opens it with ?check in headless Chromium
(SwiftShader's WebGL 1 when there is no GPU) and waits for the page's own check (web/web_check.cpp), which the
page POSTs to /result. Prints the page's report; exits 0 only on its PASS line, 1 on FAIL, on no answer within
--timeout seconds, or when Chromium exits first. Optional: --screenshot FILE also saves a screenshot of the
page in its interactive mode (scripts/web_screenshot.sh uses it for doc/images/web.png)."""
import argparse
import functools
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

    def do_POST(self):
        if self.path != "/result":
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


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--chromium", required=True)
    parser.add_argument("--page-dir", required=True)
    parser.add_argument("--page", default="lidr_web.html")
    parser.add_argument("--timeout", type=float, default=480.0)
    parser.add_argument("--screenshot", help="also save a screenshot of the interactive page here")
    args = parser.parse_args()

    page = os.path.join(args.page_dir, args.page)
    if not os.path.isfile(page):
        print(f"web.chromium: {page} not found: build the page first (bash scripts/setup.sh web)", file=sys.stderr)
        return 1
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Handler, directory=args.page_dir))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_address[1]}/{args.page}"

    # Chromium's helper processes may still write into the profile while they exit: cleanup errors are ignored.
    with tempfile.TemporaryDirectory(prefix="lidr-web-chromium-", ignore_cleanup_errors=True) as profile:
        log_path = os.path.join(profile, "chromium.log")
        with open(log_path, "w") as log:
            start = time.monotonic()
            browser = subprocess.Popen(chromium_command(args.chromium, os.path.join(profile, "profile"),
                                                        [url + "?check"]),
                                       stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
            try:
                while not Handler.result_ready.wait(0.5):
                    if browser.poll() is not None:
                        break
                    if time.monotonic() - start > args.timeout:
                        break
            finally:
                # The whole process group: the browser and its renderer, GPU and utility processes.
                try:
                    os.killpg(browser.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                browser.wait()
        elapsed = time.monotonic() - start
        if Handler.result is None:
            with open(log_path, errors="replace") as log:
                tail = log.read()[-4000:]
            why = "Chromium exited" if browser.returncode is not None and elapsed <= args.timeout else "timed out"
            print(f"web.chromium: FAIL: no result from the page after {elapsed:.0f} s ({why}); Chromium's log:\n"
                  f"{tail}", file=sys.stderr)
            server.shutdown()
            return 1
        print(Handler.result)
        print(f"web.chromium: the page answered after {elapsed:.1f} s (Chromium start, wasm load, check)")

        if args.screenshot:
            shot = subprocess.run(chromium_command(args.chromium, os.path.join(profile, "profile-shot"),
                                                   ["--window-size=1120,620", "--virtual-time-budget=20000",
                                                    f"--screenshot={os.path.abspath(args.screenshot)}", url]),
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=args.timeout)
            print(f"web.chromium: screenshot {args.screenshot} (exit {shot.returncode})")
        last = Handler.result.strip().splitlines()[-1] if Handler.result.strip() else ""
        if not last.startswith("PASS"):
            with open(log_path, errors="replace") as log:
                print("web.chromium: Chromium's log (the page's console):\n" + log.read()[-6000:], file=sys.stderr)
    server.shutdown()
    return 0 if last.startswith("PASS") else 1


if __name__ == "__main__":
    sys.exit(main())
