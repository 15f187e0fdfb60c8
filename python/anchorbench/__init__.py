"""anchorbench: online initialization of UWB anchors (Delama et al., IROS 2025) from Python.

The C++ core and engine do the work (the GIL released); this package reads their results into
pandas DataFrames. Every result keeps the files the command line writes, byte for byte, and
saves them with ``result.save(folder)``. docs/python.md shows the API by example.
"""

from __future__ import annotations

import io
import os
from typing import Iterable, Mapping, Optional, Sequence, Union

from ._anchorbench import (  # noqa: F401  (the module's API)
    Config,
    Event,
    Files,
    FrontEnd as _FrontEnd,
    InputError,
    SolveResult,
    closest_point_pdop,
    geometry_pdop,
    parts,
    register_solver,
    register_trigger,
)
from . import _anchorbench

__all__ = [
    "Config", "Event", "FrontEnd", "InputError", "Result", "SolveResult", "closest_point_pdop", "geometry_pdop",
    "load_config", "navigate", "parts", "register_solver", "register_trigger", "replay", "run", "simulate", "solve",
    "sweep",
]

ConfigLike = Union[None, str, os.PathLike, Mapping, Config]


def load_config(config: ConfigLike = None, overrides: Iterable[str] = (), name: str = "experiment") -> Config:
    """An experiment config from a YAML file, a dict in the file schema (docs/config.md), or the defaults.

    ``overrides`` are KEY=VALUE strings, as ``--set`` takes them. Bad input raises InputError with
    the command line's one-line message (the file and key).
    """
    overrides = [str(o) for o in overrides]
    if isinstance(config, Config):
        if overrides:
            raise InputError("overrides need a file or a dict, not a loaded Config")
        return config
    if config is None:
        config = {}
    if isinstance(config, Mapping):
        import yaml  # Debian's python3-yaml

        return _anchorbench._load_config_text(yaml.safe_dump(dict(config), sort_keys=False), f"{name}.yaml", overrides)
    return _anchorbench._load_config_file(os.fspath(config), overrides)


def solve(p_world_tag, range_m, solver: str = "lm_adaptive", config: ConfigLike = None) -> SolveResult:
    """Solves for an anchor (position and range bias) from tag positions (N, 3) and ranges (N,).

    ``solver`` is a registered name (``ab.parts()["solvers"]``); ``config`` sets its options
    (``estimator.ls``, ``estimator.nls``). Arrays of float64 are read without a copy.
    """
    return _anchorbench.solve(p_world_tag, range_m, solver, None if config is None else load_config(config))


class Result:
    """The files of a run, sweep, replay or simulation, with each CSV as a DataFrame."""

    def __init__(self, files: Files):
        self._files = files
        self._frames = {}

    @property
    def names(self) -> list:
        return list(self._files.names)

    def text(self, name: str) -> str:
        """A file's text, exactly as the command line writes it."""
        return self._files.text(name)

    def frame(self, name: str):
        """A CSV file as a pandas DataFrame (read once, then kept)."""
        if name not in self._frames:
            import pandas

            self._frames[name] = pandas.read_csv(io.StringIO(self.text(name)), keep_default_na=False,
                                                 na_values=[""])
        return self._frames[name]

    def __getattr__(self, attribute: str):
        if attribute.startswith("_"):
            raise AttributeError(attribute)
        name = attribute + ".csv"
        if name in self._files.names:
            return self.frame(name)
        raise AttributeError(f"no {name} in this result (files: {', '.join(self._files.names)})")

    def save(self, folder: Union[str, os.PathLike], overwrite: bool = False) -> None:
        """Writes the files into ``folder``, whole or not at all (an existing folder only with overwrite)."""
        self._files.save(os.fspath(folder), overwrite)

    def __repr__(self) -> str:
        return f"Result({', '.join(self._files.names)})"


def _with(config: ConfigLike, overrides: Iterable[str], seed: Optional[int], realizations: Optional[int]) -> Config:
    overrides = list(overrides)
    if seed is not None:
        overrides.append(f"seed={int(seed)}")
    if realizations is not None:
        overrides.append(f"realizations={int(realizations)}")
    return load_config(config, overrides)


def run(config: ConfigLike, *, overrides: Iterable[str] = (), seed: Optional[int] = None,
        realizations: Optional[int] = None, threads: int = 0) -> Result:
    """The Monte Carlo run of ``anchorbench run``: attempts, summary and timing as DataFrames.

    ``threads`` 0 takes OMP_NUM_THREADS, else every core; the bytes do not depend on it.
    """
    return Result(_anchorbench._run(_with(config, overrides, seed, realizations), int(threads)))


def sweep(config: ConfigLike, axes: Union[Mapping[str, str], Sequence[str]] = (), *, overrides: Iterable[str] = (),
          realizations: Optional[int] = None, threads: int = 0) -> Result:
    """``anchorbench sweep``: ``axes`` as {"estimator.trigger.pdop_threshold": "0.5,1,2"} or ["KEY=VALUES", ...]."""
    if isinstance(axes, Mapping):
        axes = [f"{key}={values}" for key, values in axes.items()]
    return Result(_anchorbench._sweep(_with(config, overrides, None, realizations), [str(a) for a in axes], int(threads)))


def navigate(config: ConfigLike, *, overrides: Iterable[str] = (), seed: Optional[int] = None,
             realizations: Optional[int] = None, threads: int = 0) -> Result:
    """``anchorbench navigate`` (docs/navigation.md): each trigger's anchors in a drifting robot's filter;
    navigation, navigation_summary and navigation_error as DataFrames. The config needs a 'navigation' section."""
    return Result(_anchorbench._navigate(_with(config, overrides, seed, realizations), int(threads)))


def replay(poses: Union[str, os.PathLike], ranges: Union[str, os.PathLike, Sequence[Union[str, os.PathLike]]],
           anchors: Union[None, str, os.PathLike] = None, config: ConfigLike = None, *,
           repeated_poses: str = "error", out_of_order: str = "sort", navigate: bool = False) -> Result:
    """``anchorbench replay`` of a recorded log (docs/real_data.md): estimates.csv and the replay summary;
    with ``navigate``, also the navigation filter on the log with synthetic odometry (``replay --navigate``)."""
    if isinstance(ranges, (str, os.PathLike)):
        ranges = [ranges]
    loaded = None if config is None else load_config(config)
    return Result(_anchorbench._replay(os.fspath(poses), [os.fspath(r) for r in ranges],
                                       "" if anchors is None else os.fspath(anchors), loaded, repeated_poses,
                                       out_of_order, bool(navigate)))


def simulate(config: ConfigLike, realization: int = 0, *, seed: Optional[int] = None,
             overrides: Iterable[str] = ()) -> Result:
    """``anchorbench simulate``: one realization's poses, ranges and anchors (the truth)."""
    return Result(_anchorbench._simulate(_with(config, overrides, seed, None), int(realization)))


class FrontEnd(_FrontEnd):
    """The online front end (estimator::FrontEnd) with a config's chains: one initializer per trigger and anchor.

    Feed poses and ranges one at a time (``add_pose``, ``add_range``, ``add_sample``) or as arrays
    (``add_poses``, ``add_ranges``, ``add_samples``), then ``take_events()``.
    """

    def __init__(self, config: ConfigLike = None, defer_solves: bool = False):
        super().__init__(None if config is None else load_config(config), defer_solves)
