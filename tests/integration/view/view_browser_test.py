#!/usr/bin/env python3
"""ifar view in a real browser. Starts the whole simulated stack (config/launch/sim_demo.yaml: simulator,
drivers, planner, executive, recorder) and `ifar view` on private LCM, lidar and HTTP ports, opens the page in
headless Chromium through chromedriver (W3C WebDriver over HTTP, Python's standard library only) and checks
what the page shows: live data, the graph's vertices, every daemon in the health panel, a vehicle that moves,
a scale bar that matches the zoom, pause that freezes and resume that thaws. Then the stack stops and the log
its recorder wrote is replayed with `ifar replay`: the page starts the trajectory again and shows the replayed
graph and heartbeats. Saves a screenshot of each phase.
    view_browser_test.py            (PATH with build/bin first; IFAR_SOURCE_DIR, IFAR_BINARY_DIR set by ctest)"""
import base64
import json
import math
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BINARY = os.environ.get("IFAR_BINARY_DIR", os.path.join(SOURCE, "build"))
LCM_URL = "udpm://239.255.76.67:7881?ttl=0"
LIDAR_PORT = "23881"
DAEMONS = {"sim", "velodyne-driver", "force-driver", "motor-driver", "planner", "executive", "recorder"}
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--window-size=1500,950"]
STARTED = time.monotonic()


def log(text):
    print(f"[{time.monotonic() - STARTED:5.1f} s] {text}", flush=True)


def fail(text):
    log("FAIL: " + text)
    raise SystemExit(1)


def free_port():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


class WebDriver:
    """The few W3C WebDriver commands the test needs, against chromedriver on loopback."""

    def __init__(self, port):
        self.base = f"http://127.0.0.1:{port}"
        self.session = None

    def call(self, method, path, body=None):
        data = None if body is None else json.dumps(body).encode()
        request = urllib.request.Request(self.base + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=30) as answer:
                return json.loads(answer.read() or b"{}").get("value")
        except urllib.error.HTTPError as error:
            fail(f"WebDriver {method} {path}: {error.code} {error.read()[:400]!r}")

    def wait_ready(self, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            try:
                with urllib.request.urlopen(self.base + "/status", timeout=2) as answer:
                    if json.loads(answer.read())["value"]["ready"]:
                        return
            except (OSError, ValueError, KeyError):
                pass
            time.sleep(0.1)
        fail("chromedriver did not become ready")

    def start(self, user_data_dir):
        options = {"binary": shutil.which("chromium"), "args": CHROMIUM_FLAGS + [f"--user-data-dir={user_data_dir}"]}
        value = self.call("POST", "/session", {"capabilities": {"alwaysMatch": {
            "browserName": "chrome", "goog:chromeOptions": options}}})
        self.session = value["sessionId"]

    def open(self, url):
        self.call("POST", f"/session/{self.session}/url", {"url": url})

    def script(self, source):
        return self.call("POST", f"/session/{self.session}/execute/sync", {"script": source, "args": []})

    def click(self, css):
        element = self.call("POST", f"/session/{self.session}/element", {"using": "css selector", "value": css})
        self.call("POST", f"/session/{self.session}/element/{list(element.values())[0]}/click", {})

    def screenshot(self, path):
        with open(path, "wb") as picture:
            picture.write(base64.b64decode(self.call("GET", f"/session/{self.session}/screenshot")))
        log(f"screenshot: {path}")

    def quit(self):
        if self.session:
            self.call("DELETE", f"/session/{self.session}")


def summary(driver):
    return driver.script("return window.ifarView ? window.ifarView.summary() : null;")


def wait_for(driver, what, predicate, seconds):
    deadline = time.monotonic() + seconds
    state = None
    while time.monotonic() < deadline:
        state = summary(driver)
        if state and state["errors"]:
            fail(f"the page failed while waiting for {what}: {state['errors']}")
        if state and predicate(state):
            log(f"page shows {what}")
            return state
        time.sleep(0.25)
    fail(f"the page did not show {what} within {seconds} s; last summary: {json.dumps(state)[:1500]}")


def scale_bar_metres(text):
    match = re.fullmatch(r"([0-9.]+) (m|cm)", text)
    if not match:
        fail(f"scale bar text '{text}' is not a length")
    return float(match.group(1)) * (0.01 if match.group(2) == "cm" else 1.0)


def stop(process, name):
    if process and process.poll() is None:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            log(f"{name} did not stop on SIGINT; killing it")
            process.kill()
            process.wait()


def main():
    for program in ("chromium", "chromedriver"):
        if not shutil.which(program):
            fail(f"{program} is not installed: install chromium and chromium-driver (scripts/setup does)")
    work = tempfile.mkdtemp(prefix="ifar_view_browser_")
    environment = dict(os.environ, LCM_DEFAULT_URL=LCM_URL, IFAR_LIDAR_PORT=LIDAR_PORT, IFAR_LOG_DIR=work)
    launch = view = chromedriver = replay = None
    driver = None
    try:
        launch = subprocess.Popen(["ifar", "launch", "config/launch/sim_demo.yaml", "--duration", "90", "--no-colour"],
                                  cwd=SOURCE, env=environment, stdout=open(os.path.join(work, "launch.out"), "w"),
                                  stderr=subprocess.STDOUT)
        view = subprocess.Popen(["ifar", "view", "--port", "0", "--address", "127.0.0.1", "--lcm-url", LCM_URL],
                                cwd=SOURCE, env=environment, stdout=subprocess.PIPE, stderr=open(os.path.join(work, "view.err"), "w"),
                                text=True)
        first_line = view.stdout.readline()
        match = re.search(r"open (http://127\.0\.0\.1:\d+/)", first_line)
        if not match:
            fail(f"ifar view did not say where to open it: '{first_line.strip()}'")
        url = match.group(1)
        log(f"ifar view at {url}")
        driver_port = free_port()
        chromedriver = subprocess.Popen(["chromedriver", f"--port={driver_port}"], stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)
        driver = WebDriver(driver_port)
        driver.wait_ready(15)
        driver.start(os.path.join(work, "chromium-profile"))
        driver.open(url)

        live = wait_for(driver, "a connection and poses", lambda s: s["connected"] and s["pose"] is not None, 20)
        start_pose = live["pose"]
        state = wait_for(driver, "the DV-graph, a path, every daemon healthy and the vehicle moving", lambda s: (
            s["graph"] is not None and s["graph"]["vertices"] > 0 and s["pathWaypoints"] >= 2
            and DAEMONS <= {h["process"] for h in s["health"] if h["health"] == "OK" and (h["ageS"] or 0) < 3}
            and math.hypot(s["pose"]["x"] - start_pose["x"], s["pose"]["y"] - start_pose["y"]) > 1.0
            and s["trajectoryPoints"] > 10), 40)
        log(f"graph {state['graph']}, mode {state['mode']}, pose ({state['pose']['x']:.2f}, {state['pose']['y']:.2f})")

        # The panel is redrawn with the picture: poll until it has caught up with the data.
        deadline, shown = time.monotonic() + 10, {}
        while time.monotonic() < deadline:
            rows = driver.script(
                "return [...document.querySelectorAll('#health-table tr[data-process]')].map(r => "
                "[r.dataset.process, r.querySelector('td.health').textContent]);")
            shown = {process: health for process, health in rows}
            if DAEMONS <= set(shown) and all(shown[daemon] == "OK" for daemon in DAEMONS):
                break
            time.sleep(0.25)
        else:
            fail(f"the health panel lists {shown}, expected {sorted(DAEMONS)} all OK; {json.dumps(summary(driver))[:800]}")
        log(f"health panel: {', '.join(sorted(shown))}")
        state = summary(driver)

        metres = scale_bar_metres(state["scaleBar"])
        # The scale and the frame count read in the same script as the zoom: a frame drawn since then is
        # drawn at the new scale (the page redraws every 100 ms, so a count read earlier proves nothing).
        before_zoom, frames_at_zoom = driver.script(
            "const s = window.ifarView.summary(); window.ifarView.zoom(4); return [s.pixelsPerMetre, s.drawn.frames];")
        zoomed = wait_for(driver, "the zoomed picture", lambda s: s["drawn"]["frames"] > frames_at_zoom, 5)
        zoomed_metres = scale_bar_metres(zoomed["scaleBar"])
        for length, pixels_per_metre in ((metres, state["drawn"]["pixelsPerMetre"]),
                                         (zoomed_metres, zoomed["drawn"]["pixelsPerMetre"])):
            if not 40 <= length * pixels_per_metre <= 130:
                fail(f"the scale bar's {length} m would be {length * pixels_per_metre:.0f} px at the drawn scale")
        if not (abs(zoomed["pixelsPerMetre"] / before_zoom - 4) < 1e-6 and zoomed_metres < metres):
            fail(f"zoom x4: {before_zoom} -> {zoomed['pixelsPerMetre']} px/m, bar {metres} -> {zoomed_metres} m")
        driver.script("window.ifarView.fit();")

        # The push: the executive's mode and the bumper force as the page shows them.
        pushing = wait_for(driver, "the push (mode push, bumper force over 20 N)",
                           lambda s: s["mode"] == "push" and (s["force"] or 0) > 20, 45)
        log(f"pushing with {pushing['force']:.0f} N at ({pushing['pose']['x']:.2f}, {pushing['pose']['y']:.2f})")
        driver.click("#follow")
        driver.script("window.ifarView.zoom(2.5);")
        time.sleep(1.0)
        followed = summary(driver)
        offset = math.hypot(followed["centre"]["x"] - followed["pose"]["x"], followed["centre"]["y"] - followed["pose"]["y"])
        if not followed["following"] or offset > 0.5:
            fail(f"Follow: the view's centre is {offset:.2f} m from the vehicle")
        driver.screenshot(os.path.join(BINARY, "tests", "view_browser_live.png"))
        driver.click("#follow")

        driver.click("#pause")
        paused = summary(driver)
        time.sleep(1.5)
        still = summary(driver)
        if not paused["paused"] or still["messages"] != paused["messages"] or still["pose"] != paused["pose"]:
            fail(f"pause did not freeze the page: {paused['messages']} -> {still['messages']} messages")
        driver.click("#pause")
        wait_for(driver, "messages again after resume",
                 lambda s: not s["paused"] and s["messages"] > still["messages"] + 50, 5)

        live_end = summary(driver)["pose"]
        stop(launch, "ifar launch")
        logs = [name for name in os.listdir(work) if name.startswith("demo-") and ".lcmlog" in name]
        if not logs:
            fail(f"the recorder wrote no log in {work}")
        log_path = os.path.join(work, sorted(logs)[0])
        log(f"replaying {log_path}")
        replay = subprocess.Popen(["ifar", "replay", log_path, "--lcm-url", LCM_URL, "--speed", "2", "--quiet"],
                                  env=environment, stdout=subprocess.DEVNULL, stderr=open(os.path.join(work, "replay.err"), "w"))
        # The log starts before the end of the live run: its poses, graphs and beats are stamped earlier.
        replayed = wait_for(driver, "the replay: the trajectory started again, a graph and beats from the log", lambda s: (
            s["pose"] is not None and s["pose"]["utime"] < live_end["utime"] - 4e6 and s["trajectoryPoints"] > 0
            and s["graph"] is not None and s["graph"]["utime"] < live_end["utime"] - 4e6 and s["graph"]["vertices"] > 0
            and {"planner", "executive", "sim"} <= {h["process"] for h in s["health"]
                                                    if h["utime"] < live_end["utime"] - 4e6 and (h["ageS"] or 99) < 3}), 20)
        log(f"replayed graph {replayed['graph']}, pose ({replayed['pose']['x']:.2f}, {replayed['pose']['y']:.2f})")
        driver.screenshot(os.path.join(BINARY, "tests", "view_browser_replay.png"))
        log("1 passed, 0 failed")
        return 0
    finally:
        if driver:
            try:
                driver.quit()
            except SystemExit:
                pass
        for process, name in ((replay, "ifar replay"), (launch, "ifar launch"), (view, "ifar view"),
                              (chromedriver, "chromedriver")):
            stop(process, name)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
