"""Solves release the GIL, and Ctrl-C stops a long solve with KeyboardInterrupt instead of waiting for it.

Neither test reads a clock. The GIL test stops the interpreter from switching threads on its own (a switch interval
of 1000 s), so that another Python thread can run during the solve only if the solve releases the GIL. The Ctrl-C
test sends SIGINT once the main thread is known to be inside the C++ call. How soon a cancelled solve stops is the
C++ tests' to show: SolveCancellation.* in core and SolveWorker.ANewerRequestStopsASolveInsideItsInterfaceKernels
count the checks a cancelled solve asks.
"""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import skinlayer

# A long single solve in a child process: a skin's 31 wavelengths at the most ordinates (tens of seconds on two
# cores). A helper thread sends SIGINT once the main thread stands on the line of skinlayer.solve that calls into
# C++: the pending signal is then first seen by the C++ call's own check, never by the interpreter before it.
LONG_SOLVE = textwrap.dedent("""
    import inspect, os, signal, sys, threading, time
    import skinlayer

    lines, first = inspect.getsourcelines(skinlayer.solve)
    call_line = first + next(k for k, line in enumerate(lines) if "_skinlayer.solve(" in line)
    main = threading.get_ident()

    def interrupt_inside_the_call():
        while True:
            frame = sys._current_frames().get(main)
            if frame is not None and frame.f_code is skinlayer.solve.__code__ and frame.f_lineno == call_line:
                os.kill(os.getpid(), signal.SIGINT)
                return
            time.sleep(0.001)

    material = skinlayer.Material.preset("skin-fair", ordinates=256)
    threading.Thread(target=interrupt_inside_the_call, daemon=True).start()
    try:
        skinlayer.solve(material)
        print("finished", flush=True)
    except KeyboardInterrupt as interrupt:
        last = interrupt.__traceback__
        while last.tb_next is not None:
            last = last.tb_next
        inside = last.tb_frame.f_code is skinlayer.solve.__code__ and last.tb_lineno == call_line
        print("interrupted", "inside the call" if inside else "elsewhere", flush=True)
""")


def test_other_python_threads_run_while_a_solve_runs():
    material = skinlayer.Material.preset("skin-medium")
    ticks = 0
    counts = {}
    done = threading.Event()

    def solve():
        counts["before"] = ticks
        skinlayer.solve(material)
        counts["after"] = ticks
        done.set()

    previous = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)  # no forced switches: a thread holding the GIL keeps it until it releases it
    try:
        worker = threading.Thread(target=solve)
        worker.start()
        while not done.is_set():
            ticks += 1
            time.sleep(1e-4)  # blocks, so releases the GIL: the worker takes it whenever it asks
        worker.join()
    finally:
        sys.setswitchinterval(previous)
    # Had the solve held the GIL, this thread could not have ticked between the worker's two reads.
    assert counts["after"] > counts["before"], counts


def test_ctrl_c_interrupts_a_long_solve():
    process = subprocess.Popen([sys.executable, "-c", LONG_SOLVE], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=os.environ.copy())
    out, err = process.communicate()
    assert process.returncode == 0, err
    assert out.strip() == "interrupted inside the call", (out, err)
