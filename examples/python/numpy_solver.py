#!/usr/bin/python3
"""A solver written in numpy, registered by name and stress-tested against lm_adaptive on Table I's trials.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/numpy_solver.py --realizations 10 --figure /tmp/cdf.png

Both solvers see the same simulated trials (the same seed, filter and triggers): only the solve
differs. Prints each row's median and mean error per solver and trigger, and draws the error CDF.
Only converged solves count as initialized: plain Gauss-Newton from the centroid diverges on poor
geometry (metres to 1e11 m off after 30 steps), so a solve that has not converged reports
`numerical_failure`, a failure on which the initializer waits for more data, as lm_adaptive's own
failures do. Reporting `max_iterations` instead would count every diverged solve as an anchor.
"""

import argparse

import numpy as np

import anchorbench as ab


def gauss_newton(p_world_tag, range_m):
    """Plain Gauss-Newton on (p_A, gamma), L2, from the tags' centroid raised by 1 m."""
    x = np.append(p_world_tag.mean(axis=0) + [0.0, 0.0, 1.0], 0.0)
    for iteration in range(30):
        diff = x[:3] - p_world_tag
        dist = np.linalg.norm(diff, axis=1)
        if not np.all(dist > 1e-9):
            return x[:3], float(x[3]), "numerical_failure"
        jacobian = np.column_stack([diff / dist[:, None], np.ones(len(dist))])
        step, *_ = np.linalg.lstsq(jacobian, range_m - dist - x[3], rcond=None)
        x += step
        if not np.all(np.isfinite(x)):
            break
        if np.linalg.norm(step) < 1e-9:
            return x[:3], float(x[3]), "converged"
    return x[:3], float(x[3]), "numerical_failure"  # not converged: no estimate (see the docstring)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--config", default="configs/table1.yaml")
    parser.add_argument("--realizations", type=int, default=10)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--figure", help="where to draw the error CDF (PNG)")
    args = parser.parse_args()

    ab.register_solver("numpy_gauss_newton", gauss_newton, "plain Gauss-Newton in numpy (examples/python)")
    triggers = "estimator.triggers=[fixed_window,pdop_closest_point]"
    runs = {solver: ab.run(args.config, overrides=[f"estimator.solver={solver}", triggers],
                           realizations=args.realizations, threads=args.threads)
            for solver in ["lm_adaptive", "numpy_gauss_newton"]}
    print("initialized: converged solves only (a numpy_gauss_newton solve that does not converge is a failure)")
    for solver, result in runs.items():
        print(f"\n{solver}")
        print(result.summary[["row", "method", "init", "avg_m", "med_m", "gt1m"]].to_string(index=False))

    if args.figure:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        for solver, result in runs.items():
            for method, style in [("fixed_window", "--"), ("pdop_closest_point", "-")]:
                errors = np.sort(result.attempts.query("method == @method and initialized == 1")["err_m"].to_numpy())
                ax.plot(errors, np.arange(1, len(errors) + 1) / max(len(errors), 1), style, label=f"{solver}, {method}")
        ax.set_xscale("log")
        ax.set_xlabel("anchor error (m)")
        ax.set_ylabel("share of initialized anchors")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)
        print(f"\nwrote {args.figure}")


if __name__ == "__main__":
    main()
