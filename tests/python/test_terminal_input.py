"""`skinlayer eval` with its standard input on a terminal says what it waits for instead of waiting silently."""

import os
import pty
import subprocess


def test_eval_on_a_terminal_says_it_reads_rows_and_how_to_end_them():
    master, slave = pty.openpty()
    run = subprocess.Popen([os.environ["SKINLAYER_EXECUTABLE"], "eval"], stdin=slave, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    os.close(slave)
    try:
        first = run.stderr.readline()
        os.write(master, b"\x04")  # Ctrl-D: the end of the input
        run.wait(timeout=60)
    finally:
        os.close(master)
        if run.poll() is None:
            run.kill()
    assert first.startswith("skinlayer: eval: reading rows theta_i,theta_o,phi")
    assert "Ctrl-D" in first and "< angles.csv" in first


def test_eval_from_a_pipe_reads_silently():
    run = subprocess.run([os.environ["SKINLAYER_EXECUTABLE"], "eval"], input="0,0,0\n", capture_output=True,
                         text=True, timeout=120)
    assert run.returncode == 0
    assert run.stderr == ""
