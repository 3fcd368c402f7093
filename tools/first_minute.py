#!/usr/bin/env python3
"""A new player's first minute, timed: launch the game in a real window, press Enter on the
title (Play Pachinko, the default: Classic), then hold and let go Space on the rules card
(it starts the game and fires the first shot), all with xdotool as a person would, waiting for each screen to show before acting on
it and pausing on it as long as a first-time player reads it. Prints each step's second
since launch and the first shot's; writes screenshots to build/look/first_minute_*.png.

Run it on an X display (tools/first_minute.sh starts one under Xvfb with a scratch user
folder, so it plays as a new player). Needs xdotool and ImageMagick's import and convert.
Exit status 0 when the shot was fired, 1 when a screen never came (it says which).
"""

import os
import subprocess
import sys
import time

# Seconds a first-time player spends on each screen before acting (reading, finding).
READ_MENU = 1.5
READ_CARD = 4.0
# Longest a screen may take to show, seconds.
SCREEN_TIMEOUT = 40.0
GRAB = (320, 180)  # screenshots are read at this size
OUT = "build/look"

start = time.monotonic()
steps = []


def since() -> float:
    return time.monotonic() - start


def note(what: str) -> None:
    steps.append((since(), what))
    print(f"{since():6.1f} s  {what}", flush=True)


def run(*args: str) -> str:
    return subprocess.run(args, capture_output=True, text=True, check=False).stdout


def window() -> tuple:
    """The game window's x, y, width and height on the screen, or None."""
    found = run("xdotool", "search", "--name", "Board Studio").split()
    if not found:
        return None
    geometry = run("xdotool", "getwindowgeometry", "--shell", found[-1])
    values = dict(line.split("=", 1) for line in geometry.split() if "=" in line)
    return int(values["X"]), int(values["Y"]), int(values["WIDTH"]), int(values["HEIGHT"])


def grab(win: tuple) -> list:
    """The window as GRAB-sized rows of (r, g, b)."""
    x, y, w, h = win
    raw = subprocess.run(
        ["import", "-silent", "-window", "root", "-crop", f"{w}x{h}+{x}+{y}", "+repage",
         "-resize", f"{GRAB[0]}x{GRAB[1]}!", "-depth", "8", "rgb:-"],
        capture_output=True, check=False).stdout
    px = [tuple(raw[i:i + 3]) for i in range(0, len(raw) - 2, 3)]
    return [px[r * GRAB[0]:(r + 1) * GRAB[0]] for r in range(GRAB[1])]


def find(img: list, test, fx0: float = 0.0) -> tuple:
    """Centre (fractions of the window) of the pixels passing `test`, or None."""
    hits = [(c, r) for r, row in enumerate(img) for c, p in enumerate(row)
            if c >= fx0 * GRAB[0] and test(p)]
    if len(hits) < 3:
        return None
    return (sum(h[0] for h in hits) / len(hits) / GRAB[0] + 0.5 / GRAB[0],
            sum(h[1] for h in hits) / len(hits) / GRAB[1] + 0.5 / GRAB[1])


def gold(p: tuple) -> bool:
    return p[0] > 150 and p[0] > p[2] + 60


def has_gold(img: list, fx0: float, fy0: float, fx1: float, fy1: float) -> bool:
    """True when the region holds gold writing (a screen's title)."""
    rows = img[int(fy0 * GRAB[1]):int(fy1 * GRAB[1])]
    return sum(1 for row in rows for p in row[int(fx0 * GRAB[0]):int(fx1 * GRAB[0])]
               if gold(p)) >= 20


def play_green(p: tuple) -> bool:
    return p[1] > 120 and p[1] > p[0] + 50 and p[1] > p[2] + 30


def wait_for(what: str, ready) -> tuple:
    """Polls the window until `ready(img)` answers something; returns (window, answer)."""
    limit = since() + SCREEN_TIMEOUT
    while since() < limit:
        win = window()
        if win is not None:
            answer = ready(grab(win))
            if answer:
                note(what)
                return win, answer
        time.sleep(0.2)
    shot("stuck")
    print(f"first minute: {what} never showed in {SCREEN_TIMEOUT:.0f} s (the screen: "
          f"{OUT}/first_minute_stuck.png, window {window()})", file=sys.stderr)
    sys.exit(1)


def key(win: tuple, name: str, hold: float = 0.0) -> None:
    """Presses `name` in the game's window (held `hold` seconds)."""
    found = run("xdotool", "search", "--name", "Board Studio").split()
    if found:
        run("xdotool", "windowfocus", "--sync", found[-1])
    run("xdotool", "keydown", name)
    time.sleep(max(hold, 0.05))
    run("xdotool", "keyup", name)


def shot(name: str) -> None:
    run("import", "-silent", "-window", "root", f"{OUT}/first_minute_{name}.png")


def main() -> None:
    os.makedirs(OUT, exist_ok=True)
    game = subprocess.Popen(
        ["tools/godot.sh", "--rendering-driver", "opengl3", "--path", "."],
        stdout=open(f"{OUT}/first_minute.log", "w"), stderr=subprocess.STDOUT)
    note("launched")
    try:
        # the title's gold letters
        win, _ = wait_for("main menu shown", lambda img: has_gold(img, .30, .15, .70, .32))
        time.sleep(READ_MENU)
        key(win, "Return")  # Play Pachinko, the focused default
        note("pressed Enter (Play Pachinko)")
        win, play = wait_for("rules card shown",
                             lambda img: find(img, play_green, 0.0))
        time.sleep(READ_CARD)
        # Space on the card starts the game and draws the flipper back; let go, it fires
        key(win, "space", hold=0.6)
        note("FIRST SHOT fired (Space held 0.6 s and let go)")
        time.sleep(1.0)
        shot("after_shot")
    finally:
        game.terminate()
        game.wait(timeout=20)
    first = next(t for t, what in steps if what.startswith("FIRST SHOT fired"))
    print(f"first minute: first shot {first:.1f} s after launch, 2 key presses "
          f"(reading pauses {READ_MENU + READ_CARD:.1f} s of it)")


if __name__ == "__main__":
    main()
