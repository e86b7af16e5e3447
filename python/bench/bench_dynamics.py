"""What calling `dynamics` from Python costs beyond the Rust call.

Times `gearwear.dynamics(case)` (argument checks, the study's thread, the Rust work,
conversion of the summary and tables to dicts and numpy arrays, the result object) against
the same Rust work timed inside Rust (`_gearwear._time_rust_dynamics`: model, steady-state
evaluation, report builder, metadata, drop), call by call, in interleaved rounds so that
load on the machine affects both alike. Not a test: run it by hand.

    python python/bench/bench_dynamics.py [--rounds 7] [--calls 40]
"""

import argparse
import statistics
import time

import gearwear as gw
from gearwear import _gearwear


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rounds", type=int, default=7)
    p.add_argument("--calls", type=int, default=40)
    a = p.parse_args()
    case = gw.Case.paper()
    for _ in range(10):  # warm-up: allocator, caches, thread creation
        gw.dynamics(case)
    _gearwear._time_rust_dynamics(case, 10)

    rust, py = [], []
    for _ in range(a.rounds):
        rust += _gearwear._time_rust_dynamics(case, a.calls)
        for _ in range(a.calls):
            t0 = time.perf_counter()
            gw.dynamics(case)
            py.append(time.perf_counter() - t0)

    def line(name, v):
        v = sorted(v)
        q1, med, q3 = v[len(v) // 4], statistics.median(v), v[3 * len(v) // 4]
        return f"{name:<22} median {med * 1e3:7.3f} ms  (quartiles {q1 * 1e3:.3f} .. {q3 * 1e3:.3f}, min {v[0] * 1e3:.3f})"

    print(f"paper case, {len(rust)} calls each, in {a.rounds} interleaved rounds")
    print(line("Rust (in-process)", rust))
    print(line("Python gw.dynamics", py))
    m_r, m_p = statistics.median(rust), statistics.median(py)
    print(f"overhead of the Python call: {(m_p / m_r - 1) * 100:+.2f} % of the median "
          f"({(m_p - m_r) * 1e6:+.0f} us); on the minima {(min(py) / min(rust) - 1) * 100:+.2f} %")


if __name__ == "__main__":
    main()
