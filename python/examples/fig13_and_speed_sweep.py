"""The paper's Fig. 13 (maximum accumulated pinion wear, dynamic against quasi-static) and a
speed sweep of the dynamic response, from gearwear's Python package.

    pip install "./python[examples]"         # from the repository's root: gearwear, matplotlib, tqdm
    python python/examples/fig13_and_speed_sweep.py --out figures/

Headless (no display): MPLBACKEND=Agg python ... The Jupyter notebook beside this file
does the same step by step.
"""

import argparse
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import gearwear as gw


def progress_printer():
    """A progress callback: a tqdm bar per run if tqdm is installed, else nothing."""
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    bars = {}

    def progress(what, done, total):
        bar = bars.setdefault(what, tqdm(total=total, desc=what, unit_scale=True))
        bar.update(done - bar.n)

    return progress


def fig13(case, out):
    """Max accumulated pinion wear against load cycles, both wear models (paper Fig. 13)."""
    w = gw.wear(case, progress=progress_printer())
    fig, ax = plt.subplots(figsize=(7, 4))
    for run, style in ((w.dynamic, "o-"), (w.quasi_static, "s--")):
        ax.plot(run.cycles, run.max_wear_pinion_um, style, label=run.mode.replace("_", "-"))
    ax.set_xlabel("load cycles")
    ax.set_ylabel("maximum pinion wear depth (µm)")
    ax.set_title("Fig. 13: maximum accumulated pinion wear")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "fig13_max_accumulated_wear.png", dpi=120)
    ratio = w.summary["ratio_max_wear_dynamic_to_static"]
    print(f"dynamic / quasi-static maximum wear after {w.dynamic.cycles[-1]:.0f} cycles: {ratio:.3f}")


def speed_sweep(case, out):
    """Max DTE and dynamic factor from 10 to 60 Hz input speed, with the speeds at which a
    mesh harmonic h z1 f_in meets a damped mesh pole marked."""
    s = gw.sweep(case, {"operating.input_speed_hz": "10:60:1"}, progress=progress_printer())
    speed = s["operating.input_speed_hz"]
    d = gw.dynamics(case)
    f_n = d.damped_frequency_hz[d.mesh_pole == 1]
    z1 = case["gear.teeth_pinion"]
    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    a1.plot(speed, s["dte_max_um"], ".-")
    a2.plot(speed, s["dynamic_factor"], ".-")
    for h in (1, 2, 3):
        for f in f_n[f_n > 1.0]:
            v = f / (h * z1)
            if speed.min() <= v <= speed.max():
                for a in (a1, a2):
                    a.axvline(v, color="grey", lw=0.8, ls=":")
                a1.annotate(f"{h}x {f:.0f} Hz", (v, a1.get_ylim()[1]), rotation=90, va="top", fontsize=7)
    a1.set_ylabel("max DTE (µm)")
    a2.set_ylabel("dynamic factor (-)")
    a2.set_xlabel("input speed (Hz)")
    a1.set_title("Speed sweep, new teeth")
    fig.tight_layout()
    fig.savefig(out / "speed_sweep.png", dpi=120)
    i = int(np.argmax(s["dynamic_factor"]))
    print(f"largest dynamic factor {s['dynamic_factor'][i]:.3f} at {speed[i]:g} Hz")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", type=Path, default=Path("."), help="folder for the PNG files")
    a = p.parse_args()
    a.out.mkdir(parents=True, exist_ok=True)
    case = gw.Case.paper()
    fig13(case, a.out)
    speed_sweep(case, a.out)


if __name__ == "__main__":
    main()
