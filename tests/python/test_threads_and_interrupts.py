"""Solves release the GIL, and Ctrl-C stops a long solve with KeyboardInterrupt instead of waiting for it."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import skinlayer

# A long single solve: a skin's 31 wavelengths at the most ordinates (seconds on two cores).
LONG_SOLVE = textwrap.dedent("""
    import sys, time
    import skinlayer
    material = skinlayer.Material.preset("skin-fair", ordinates=256)
    print("ready", flush=True)
    start = time.monotonic()
    try:
        skinlayer.solve(material)
        print("finished", time.monotonic() - start, flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic() - start, flush=True)
""")


def test_other_python_threads_run_while_a_solve_runs():
    material = skinlayer.Material.preset("skin-medium")
    ticks = 0
    done = threading.Event()

    def solve():
        skinlayer.solve(material)
        done.set()

    worker = threading.Thread(target=solve)
    start = time.monotonic()
    worker.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    elapsed = time.monotonic() - start
    # With the GIL held for the solve this thread could not tick at all until it ended.
    assert ticks >= min(50, int(elapsed * 100)), (ticks, elapsed)


def test_ctrl_c_interrupts_a_long_solve():
    process = subprocess.Popen([sys.executable, "-c", LONG_SOLVE], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=os.environ.copy())
    assert process.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    process.send_signal(signal.SIGINT)
    sent = time.monotonic()
    out, err = process.communicate(timeout=120)
    waited = time.monotonic() - sent
    assert process.returncode == 0, err
    assert out.startswith("interrupted"), out
    # The solve stops at its next stage, well before it would have finished (tens of seconds).
    assert waited < 10.0, waited
