#!/usr/bin/env python3
"""Opens eomgen's animation pages in headless Chromium (Debian's chromium) and checks them:
the body drawn at #t=T is where the simulation's own CSV puts it, screenshots at two times differ
where the body moved, and the page logs no error. Standard library only.

usage: check_animation.py EOMGEN MODELS_DIR WORK_DIR [--screenshot README_PNG]
"""
import csv
import json
import math
import os
import re
import struct
import subprocess
import sys
import zlib

EOMGEN, MODELS, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
README_SHOT = sys.argv[5] if len(sys.argv) > 5 and sys.argv[4] == "--screenshot" else None
CHROMIUM = "/usr/bin/chromium"
SIZE = (800, 600)
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def eomgen(*arguments):
    run = subprocess.run([EOMGEN, *arguments], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"eomgen {' '.join(arguments)} failed ({run.returncode}):\n{run.stderr}")
    return run


def chromium(url, *extra, window=SIZE):
    run = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-dev-shm-usage", "--enable-unsafe-swiftshader",
                          "--use-angle=swiftshader", "--force-device-scale-factor=1", "--hide-scrollbars",
                          f"--window-size={window[0]},{window[1]}", "--virtual-time-budget=4000", "--enable-logging=stderr",
                          "--v=0", *extra, url], capture_output=True, text=True, timeout=180)
    return run


# --dump-dom lays the page out in a window with the browser's bars, --screenshot in the bare
# viewport: the window whose viewport is the screenshot's, found once
dump_window = list(SIZE)


def body_attributes(html, t):
    run = chromium(f"file://{html}#t={t}", "--dump-dom", window=dump_window)
    body = re.search(r"<body([^>]*)>", run.stdout)
    if not body:
        sys.exit(f"no <body> in Chromium's DOM of {html}:\n{run.stderr[-2000:]}")
    return run, dict(re.findall(r'([a-z-]+)="([^"]*)"', body.group(1)))


def page_state(html, t):
    """The <body> attributes the page sets once it shows t."""
    run, attributes = body_attributes(html, t)
    viewport = [int(v) for v in attributes.get("data-eomgen-viewport", "0x0").split("x")]
    if viewport[1] != SIZE[1] and viewport[1] > 0:
        dump_window[1] += SIZE[1] - viewport[1]
        run, attributes = body_attributes(html, t)
    unquote = lambda s: s.replace("&quot;", '"').replace("&amp;", "&")
    uncaught = [line for line in run.stderr.splitlines() if "Uncaught" in line or ("CONSOLE" in line and "rror" in line)]
    return {"time": float(attributes.get("data-eomgen-time", "nan")),
            "errors": attributes.get("data-eomgen-errors"),
            "positions": json.loads(unquote(attributes.get("data-eomgen-positions", "{}"))),
            "screen": json.loads(unquote(attributes.get("data-eomgen-screen", "{}"))),
            "console": uncaught}


def screenshot(html, t, png):
    chromium(f"file://{html}#t={t}", f"--screenshot={png}")
    return read_png(png)


def read_png(path):
    """width, height and rows of (r, g, b) of an 8-bit RGB or RGBA PNG, as Chromium writes them"""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        at += 12 + length
    width, height, depth, color = header[:4]
    assert depth == 8 and color in (2, 6), f"{path}: bit depth {depth}, colour type {color}"
    step = 4 if color == 6 else 3
    raw, rows, previous = zlib.decompress(idat), [], bytearray(width * step)
    stride = width * step
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - step] if i >= step else 0
            b = previous[i]
            c = previous[i - step] if i >= step else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * step:x * step + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def csv_row(path, t):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return min(rows, key=lambda r: abs(float(r["t"]) - t))


def differs_near(first, second, point, reach=4):
    x0, y0 = int(round(point[0])), int(round(point[1]))
    for y in range(max(0, y0 - reach), min(first[1], y0 + reach + 1)):
        for x in range(max(0, x0 - reach), min(first[0], x0 + reach + 1)):
            if sum(abs(a - b) for a, b in zip(first[2][y][x], second[2][y][x])) > 60:
                return True
    return False


def animate_case(name, model, body, expected, t_end, times, extra=()):
    """expected(row) gives the body's position from the simulation's CSV row"""
    html, table = os.path.join(WORK, name + ".html"), os.path.join(WORK, name + ".csv")
    common = ["--t-end", str(t_end), "--dt-out", "0.01"]
    eomgen("animate", os.path.join(MODELS, model), "-o", html, *common, *extra)
    eomgen("simulate", os.path.join(MODELS, model), "-o", table, *common)
    size = os.path.getsize(html)
    check(size < 3e6, f"{name}: the page is {size / 1e6:.2f} MB, under 3 MB")
    shots = []
    for t in times:
        state = page_state(html, t)
        check(state["errors"] == "0" and not state["console"], f"{name}: no error at t = {t} {state['console'][:3]}")
        check(abs(state["time"] - t) < 1e-12, f"{name}: the page shows t = {state['time']} for #t={t}")
        drawn, want = state["positions"].get(body), expected(csv_row(table, t))
        scale = max(1e-300, max(abs(c) for c in want))
        ok = drawn is not None and all(abs(a - b) <= 2e-6 * scale for a, b in zip(drawn, want))
        check(ok, f"{name}: {body} drawn at {drawn} at t = {t}, the trajectory has {want}")
        shots.append((screenshot(html, t, os.path.join(WORK, f"{name}_{t}.png")), state["screen"][body]))
    (first, at_first), (second, at_second) = shots[0], shots[1]
    moved = math.dist(at_first, at_second)
    check(moved > 5, f"{name}: {body} moves {moved:.0f} px on the screen between t = {times[0]} and {times[1]}")
    check(differs_near(first, second, at_first) and differs_near(first, second, at_second),
          f"{name}: the screenshots differ where {body} was and where it went")
    return html


os.makedirs(WORK, exist_ok=True)
p = {"l1": 1.0, "l2": 1.0, "s": 0.05}
pendulum = animate_case("double_pendulum", "double_pendulum.toml", "bob2",
                        lambda r: [float(r["tip_x"]), float(r["tip_y"]), 0.0], 10, [0.5, 1.5], ["--trace", "bob2"])


def top_centre(r):
    psi, theta = float(r["psi"]), float(r["theta"])
    return [p["s"] * math.sin(psi) * math.sin(theta), -p["s"] * math.cos(psi) * math.sin(theta), p["s"] * math.cos(theta)]


animate_case("heavy_symmetric_top", "heavy_symmetric_top.toml", "top", top_centre, 2, [0.25, 1.0], ["--axes"])
bicycle = os.path.join(WORK, "whipple_bicycle.html")
eomgen("animate", os.path.join(MODELS, "whipple_bicycle.toml"), "-o", bicycle, "--t-end", "3")
for t in (0.5, 2.5):
    state = page_state(bicycle, t)
    check(state["errors"] == "0" and not state["console"], f"whipple_bicycle: no error at t = {t}")
    check(len(state["positions"]) >= 8, f"whipple_bicycle: {len(state['positions'])} bodies and frames drawn")
if README_SHOT:
    screenshot(pendulum, 1.2, README_SHOT)
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
