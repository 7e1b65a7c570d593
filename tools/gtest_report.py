"""gtest_report.py — googletest-style output for the Python tests in `make test`.

tools/run_tests.sh counts a binary's tests from googletest's summary lines
("[  PASSED  ] N tests.", "[  FAILED  ] N tests"); the Python tests
(tools/accuracy_test.py, tools/logic_depth_test.py, tools/congestion_test.py,
tools/synth_args_test.py) print the same lines
through run_suite, so that they are counted like the C++ ones.
"""
import importlib.util
import os
import shutil
import tempfile
import time
import traceback

TOOLS = os.path.dirname(os.path.abspath(__file__))


class Failure(Exception):
    """A check that did not hold: reported by its message, without a traceback."""


def load_tool(name):
    """tools/<name>.py loaded as a module (the tests call its functions), and its path
    (they run it as a command too)."""
    path = os.path.join(TOOLS, f"{name}.py")
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod, path


def check(cond, what):
    if not cond:
        raise Failure(what)


def run_suite(suite, tests, source):
    """Runs [(name, fn(ctx))] in order, ctx["tmp"] a temporary folder they share (removed
    afterwards); prints googletest's lines; returns the exit status. run_tests.sh passes
    googletest flags (--gtest_color=no): nothing to do with them."""
    ctx = {"tmp": tempfile.mkdtemp(prefix=f"csgrt-{suite.lower()}-")}
    try:
        return _run(suite, tests, ctx, source)
    finally:
        shutil.rmtree(ctx["tmp"], ignore_errors=True)


def _run(suite, tests, ctx, source):
    print(f"[==========] Running {len(tests)} tests from 1 test suite.", flush=True)
    failed = []
    for name, fn in tests:
        print(f"[ RUN      ] {suite}.{name}", flush=True)
        t0 = time.time()
        try:
            fn(ctx)
            print(f"[       OK ] {suite}.{name} ({int(1000 * (time.time() - t0))} ms)", flush=True)
        except Exception as e:
            msg = str(e) if isinstance(e, Failure) else traceback.format_exc()
            print(f"{source}: Failure in {suite}.{name}\n{msg}")
            print(f"[  FAILED  ] {suite}.{name} ({int(1000 * (time.time() - t0))} ms)", flush=True)
            failed.append(name)
    print(f"[==========] {len(tests)} tests from 1 test suite ran.")
    print(f"[  PASSED  ] {len(tests) - len(failed)} tests.")
    if failed:
        print(f"[  FAILED  ] {len(failed)} tests, listed below:")
        for f in failed:
            print(f"[  FAILED  ] {suite}.{f}")
    return 1 if failed else 0
