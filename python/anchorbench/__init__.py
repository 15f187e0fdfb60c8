"""anchorbench: online initialization of UWB anchors (Delama et al., IROS 2025) from Python.

The C++ core and engine do the work (the GIL released); this package reads their results into
pandas DataFrames. Every result keeps the files the command line writes, byte for byte, and
saves them with ``result.save(folder)``. docs/python.md shows the API by example.
"""

from __future__ import annotations

import io
import numbers
import os
import re
import sys
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

from ._anchorbench import (  # noqa: F401  (the module's API)
    Config,
    Event,
    Files,
    FrontEnd as _FrontEnd,
    InputError,
    SolveResult,
    closest_point_pdop,
    geometry_pdop,
    part_options,
    parts,
    register_solver,
    register_trigger,
)
from . import _anchorbench
from . import plot  # noqa: F401  (ab.plot.anchors, ab.plot.errors_over_time; matplotlib only when drawing)

__all__ = [
    "Config", "Event", "FrontEnd", "InputError", "Result", "SolveResult", "closest_point_pdop", "geometry_pdop",
    "explore", "load_config", "navigate", "part_options", "pdop_study", "parts", "register_solver", "register_trigger", "plot", "replay", "ReplayWarning", "FrontEndWarning", "run",
    "simulate", "solve", "sweep",
]

ConfigLike = Union[None, str, os.PathLike, Mapping, Config]
ProgressLike = Union[None, bool, Callable[[int, int], Any]]

_MAX_SEED = 2**63 - 1
_MAX_ID = 2**31 - 1


# --- Arguments, checked in Python words: each error an InputError naming the argument ----------

def _whole(name: str, value, low: int, high: int) -> int:
    """A whole number in [low, high] (an int or a numpy integer; never a float or a bool)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InputError(f"{name}: expected a whole number, got {value!r}")
    value = int(value)
    if not low <= value <= high:
        raise InputError(f"{name}: must be from {low} to {high}, got {value}")
    return value


def _finite(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(f"{name}: expected a number, got {value!r}")
    value = float(value)
    if value != value or value in (float("inf"), float("-inf")):
        raise InputError(f"{name}: must be finite, got {value}")
    return value


def _path(name: str, value) -> str:
    """A path as text: not empty, without a NUL byte."""
    try:
        text = os.fspath(value)
    except TypeError:
        raise InputError(f"{name}: expected a path, got {type(value).__name__}") from None
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not text:
        raise InputError(f"{name}: an empty path")
    if "\0" in text:
        raise InputError(f"{name}: {text!r} holds a NUL byte")
    return text


def _point(name: str, value):
    import numpy as np

    try:
        point = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected [x, y, z] in metres, got {value!r}") from None
    if point.shape != (3,):
        raise InputError(f"{name}: expected shape (3,), got {point.shape}")
    return point


def _ids(name: str, values, n: Optional[int] = None):
    """Ids as an int32 array: whole numbers within int32, never wrapped."""
    import numpy as np

    array = np.asarray(values)
    if array.ndim != 1 or (n is not None and len(array) != n):
        raise InputError(f"{name}: expected an array of shape ({'N' if n is None else n},), got {array.shape}")
    if array.dtype.kind not in "iu":
        if array.dtype.kind == "f" and np.all(np.isfinite(array)) and np.all(array == np.round(array)):
            array = array.astype(np.int64)
        elif len(array):
            raise InputError(f"{name}: expected whole numbers, got an array of {array.dtype}")
    if len(array) and (array.min() < -_MAX_ID - 1 or array.max() > _MAX_ID):
        raise InputError(f"{name}: ids must lie within [{-_MAX_ID - 1}, {_MAX_ID}], got {array.min()} to {array.max()}")
    return array.astype(np.int32)


def _floats(name: str, values, shape_text: str):
    import numpy as np

    try:
        return np.ascontiguousarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected numbers of shape {shape_text}") from None


def _plain(value):
    """A config dict with numpy scalars and arrays as plain Python values (what YAML writes)."""
    if isinstance(value, Mapping):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if hasattr(value, "tolist") and hasattr(value, "dtype"):  # a numpy scalar or array
        return _plain(value.tolist())
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    return value


class _Progress:
    """A progress bar (tqdm, on a terminal by default), a callback, or nothing."""

    def __init__(self, progress: ProgressLike, what: str):
        self._bar = None
        self._callback = None
        if callable(progress) and not isinstance(progress, bool):
            self._callback = progress
        elif progress or (progress is None and sys.stderr is not None and sys.stderr.isatty()):
            try:
                from tqdm import tqdm  # Debian's python3-tqdm
            except ImportError:
                return
            self._bar = tqdm(desc=what, unit="unit", leave=False)

    def callback(self):
        if self._callback is not None:
            return self._callback
        if self._bar is None:
            return None

        def update(done: int, total: int) -> None:
            self._bar.total = total
            self._bar.n = done
            self._bar.refresh()

        return update

    def __enter__(self):
        return self.callback()

    def __exit__(self, *exc) -> None:
        if self._bar is not None:
            self._bar.close()


def load_config(config: ConfigLike = None, overrides: Iterable[str] = (), name: str = "experiment") -> Config:
    """An experiment config from a YAML file, a dict in the file schema (docs/config.md), or the defaults.

    ``overrides`` are KEY=VALUE strings, as ``--set`` takes them. Bad input raises InputError with
    the command line's one-line message (the file and key).
    """
    if isinstance(overrides, (str, bytes)):
        raise InputError("overrides: expected a list of KEY=VALUE strings, got one string")
    overrides = [str(o) for o in overrides]
    if isinstance(config, Config):
        if overrides:
            raise InputError("overrides need a file or a dict, not a loaded Config")
        return config
    if config is None:
        config = {}
    if isinstance(config, Mapping):
        import yaml  # Debian's python3-yaml

        try:
            text = yaml.safe_dump(_plain(config), sort_keys=False)
        except yaml.YAMLError as error:
            raise InputError(f"config: a value YAML cannot hold: {str(error).splitlines()[0]}") from None
        return _anchorbench._load_config_text(text, f"{name}.yaml", overrides)
    if isinstance(config, (str, bytes, os.PathLike)):
        return _anchorbench._load_config_file(_path("config", config), overrides)
    raise InputError(f"config: expected a YAML path, a dict or None, got {type(config).__name__}")


def solve(p_world_tag, range_m, solver: str = "lm_adaptive", config: ConfigLike = None) -> SolveResult:
    """Solves for an anchor (position and range bias) from tag positions (N, 3) and ranges (N,).

    ``solver`` is a registered name (``ab.parts()["solvers"]``); ``config`` sets its options
    (``estimator.ls``, ``estimator.nls``). Arrays of float64 are read without a copy.
    """
    if not isinstance(solver, str):
        raise InputError(f"solver: expected a registered name, got {solver!r}")
    return _anchorbench.solve(_floats("p_world_tag", p_world_tag, "(N, 3)"), _floats("range_m", range_m, "(N,)"),
                              solver, None if config is None else load_config(config))


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
        """A CSV file as a pandas DataFrame (read once, then kept; every number exactly as written)."""
        if name not in self._frames:
            import pandas

            self._frames[name] = pandas.read_csv(io.StringIO(self.text(name)), keep_default_na=False,
                                                 na_values=[""], float_precision="round_trip")
        return self._frames[name]

    @property
    def warnings(self) -> list:
        """What the command line prints on stderr beside the files (replay: rows dropped or reordered)."""
        return [line for line in [self._files.notes.rstrip("\n")] if line]

    @property
    def replay_summary(self) -> dict:
        """A replay's replay_summary.json as a dict: the rows read, used and dropped (by reason and id)."""
        import json

        return json.loads(self.text("replay_summary.json"))

    @property
    def drops(self):
        """A replay's dropped rows as a DataFrame: kind (ranges / poses), id (anchor / tag), reason, count, first."""
        import pandas

        summary = self.replay_summary
        rows = [(kind, int(id_), reason, tally["count"], tally["first"])
                for kind, key in (("ranges", "range_drops_by_anchor"), ("poses", "pose_drops_by_tag"))
                for id_, reasons in summary[key].items() for reason, tally in reasons.items()]
        return pandas.DataFrame(rows, columns=["kind", "id", "reason", "count", "first"])

    def _replay_summary_frame(self):
        """One row per trigger of a replay: anchors, initialized, the median t_init, the errors where the
        truth is known, the most common reason to wait, and the log's samples and dropped rows."""
        import pandas

        e, log = self.estimates, self.replay_summary
        rows = []
        for method, group in e.groupby("method", sort=False):
            done = group[group["initialized"] == 1]
            waiting = group.loc[group["initialized"] != 1, "blocked_by"].dropna()
            rows.append({"method": method, "anchors": len(group), "initialized": len(done),
                         "t_init_median_s": done["t_init"].median(),
                         "err_mean_m": done["err_m"].mean() if "err_m" in done else float("nan"),
                         "err_max_m": done["err_m"].max() if "err_m" in done else float("nan"),
                         "waiting_most_for": waiting.mode().iloc[0] if len(waiting) else "",
                         "samples": log["samples"], "dropped_rows": log["dropped"]})
        return pandas.DataFrame(rows)

    def __getattr__(self, attribute: str):
        if attribute.startswith("_"):
            raise AttributeError(attribute)
        name = attribute + ".csv"
        if name in self._files.names:
            return self.frame(name)
        if attribute == "summary" and "replay_summary.json" in self._files.names:
            return self._replay_summary_frame()
        raise AttributeError(f"no {name} in this result (files: {', '.join(self._files.names)})")

    def save(self, folder: Union[str, os.PathLike], overwrite: bool = False) -> None:
        """Writes the files into ``folder``, whole or not at all (an existing folder only with overwrite).

        A folder that holds a file the result was made from (its config, a replayed log) is refused.
        """
        self._files.save(_path("folder", folder), bool(overwrite))

    def __repr__(self) -> str:
        return f"Result({', '.join(self._files.names)})"


def _with(config: ConfigLike, overrides: Iterable[str], seed: Optional[int], realizations: Optional[int]) -> Config:
    if isinstance(overrides, (str, bytes)):
        raise InputError("overrides: expected a list of KEY=VALUE strings, got one string")
    overrides = list(overrides)
    if seed is not None:
        overrides.append(f"seed={_whole('seed', seed, 0, _MAX_SEED)}")
    if realizations is not None:
        overrides.append(f"realizations={_whole('realizations', realizations, 1, 100_000_000)}")
    return load_config(config, overrides)


def _threads(threads) -> int:
    return _whole("threads", threads, 0, 8 * (os.cpu_count() or 1))


def run(config: ConfigLike, *, overrides: Iterable[str] = (), seed: Optional[int] = None,
        realizations: Optional[int] = None, threads: int = 0, progress: ProgressLike = None) -> Result:
    """The Monte Carlo run of ``anchorbench run``: attempts, summary and timing as DataFrames.

    ``threads`` 0 takes OMP_NUM_THREADS, else every core; the bytes do not depend on it.
    ``progress``: a bar on a terminal (None), always (True), never (False), or a callable(done, total)
    of realizations. Ctrl-C stops the run within about a second (KeyboardInterrupt).
    """
    config = _with(config, overrides, seed, realizations)
    with _Progress(progress, f"run {config.name}") as callback:
        return Result(_anchorbench._run(config, _threads(threads), callback))


def sweep(config: ConfigLike, axes: Union[Mapping[str, str], Sequence[str]] = (), *, overrides: Iterable[str] = (),
          realizations: Optional[int] = None, threads: int = 0, progress: ProgressLike = None) -> Result:
    """``anchorbench sweep``: ``axes`` as {"estimator.trigger.pdop_threshold": "0.5,1,2"} or ["KEY=VALUES", ...].

    ``progress`` and Ctrl-C as in run().
    """
    if isinstance(axes, Mapping):
        axes = [f"{key}={','.join(map(str, _plain(values))) if isinstance(values, (list, tuple)) else values}"
                for key, values in axes.items()]
    elif isinstance(axes, (str, bytes)):
        axes = [axes]
    config = _with(config, overrides, None, realizations)
    with _Progress(progress, f"sweep {config.name}") as callback:
        return Result(_anchorbench._sweep(config, [str(a) for a in axes], _threads(threads), callback))


def navigate(config: ConfigLike, *, overrides: Iterable[str] = (), seed: Optional[int] = None,
             realizations: Optional[int] = None, threads: int = 0, progress: ProgressLike = None) -> Result:
    """``anchorbench navigate`` (docs/navigation.md): each trigger's anchors in a drifting robot's filter;
    navigation, navigation_summary and navigation_error as DataFrames. The config needs a 'navigation' section.
    ``progress`` and Ctrl-C as in run()."""
    config = _with(config, overrides, seed, realizations)
    with _Progress(progress, f"navigate {config.name}") as callback:
        return Result(_anchorbench._navigate(config, _threads(threads), callback))


def explore(config: ConfigLike, *, overrides: Iterable[str] = (), seed: Optional[int] = None,
            realizations: Optional[int] = None, threads: int = 0, progress: ProgressLike = None) -> Result:
    """``anchorbench explore`` (docs/guidance.md): the closed loop, every policy of the config's
    'exploration' section on the same realizations; exploration and exploration_summary as DataFrames.
    ``progress`` and Ctrl-C as in run()."""
    config = _with(config, overrides, seed, realizations)
    with _Progress(progress, f"explore {config.name}") as callback:
        return Result(_anchorbench._explore(config, _threads(threads), callback))


def pdop_study(config: ConfigLike, *, every: Optional[int] = None, bin_s: Optional[float] = None,
               overrides: Iterable[str] = (), seed: Optional[int] = None, realizations: Optional[int] = None,
               threads: int = 0, progress: ProgressLike = None) -> Result:
    """``anchorbench pdop-study`` (docs/pdop_studies.md): every PDOP of the base scenario's runs, a
    checkpoint every ``every`` accepted samples (pdop_trace as a DataFrame), summarized in ``bin_s``
    bins (pdop_study.md); unset, the config's ``pdop_study`` section's (default 10 and 10 s), as
    the command line's --every and --bin-s. ``progress`` and Ctrl-C as in run()."""
    settings = []
    if every is not None:
        settings.append(f"pdop_study.every={_whole('every', every, 1, 1_000_000)}")
    if bin_s is not None:
        settings.append(f"pdop_study.bin_s={_in_range('bin_s', bin_s, 0.01, 120.0)!r}")
    if isinstance(overrides, (str, bytes)):
        raise InputError("overrides: expected a list of KEY=VALUE strings, got one string")
    config = _with(config, [*overrides, *settings], seed, realizations)
    with _Progress(progress, f"pdop-study {config.name}") as callback:
        return Result(_anchorbench._pdop_study(config, _threads(threads), callback))


LogLike = Union[str, os.PathLike, Mapping, "pandas.DataFrame"]


# The command line's words in replay's refusals, as this function's arguments.
_REPLAY_FLAGS = {"--max-range-m": "max_range_m", "--average-poses-within-m": "average_poses_within_m",
                 "--repeated-poses": "repeated_poses", "--out-of-order": "out_of_order",
                 "--sort-window-s": "sort_window_s", "--max-speed-mps": "max_speed_mps", "--strict": "strict=True",
                 "--anchors": "anchors", "--poses": "poses", "--ranges": "ranges"}


class ReplayWarning(UserWarning):
    """Rows of a replayed log were dropped or reordered (the command line's stderr summary)."""


def _in_range(name: str, value, low: float, high: float) -> float:
    value = _finite(name, value)
    if not low <= value <= high:
        raise InputError(f"{name}: must be from {low:g} to {high:g}, got {value:g}")
    return value


def _log_file(name: str, value, folder: str) -> str:
    """A path as given, or a DataFrame (or a mapping of columns) written to a CSV in `folder`: every
    float with all its digits, the columns as named (docs/real_data.md's names and aliases)."""
    if isinstance(value, (str, bytes, os.PathLike)):
        return _path(name, value)
    import pandas

    if isinstance(value, Mapping):
        value = pandas.DataFrame({str(k): v for k, v in value.items()})
    if not isinstance(value, pandas.DataFrame):
        raise InputError(f"{name}: expected a path, a DataFrame or a mapping of columns, got {type(value).__name__}")
    path = os.path.join(folder, f"{name}.csv")
    value.to_csv(path, index=False, float_format="%.17g")
    return path


def replay(poses: LogLike, ranges: Union[LogLike, Sequence[LogLike]], anchors: Optional[LogLike] = None,
           config: ConfigLike = None, *, repeated_poses: str = "error", out_of_order: str = "sort",
           navigate: bool = False, max_range_m: float = 1000.0, average_poses_within_m: float = 0.05,
           sort_window_s: float = 0.1, max_speed_mps: float = 50.0, strict: bool = False, trace: bool = False,
           certificate_trace: bool = False, warn: bool = True) -> Result:
    """``anchorbench replay`` of a recorded log (docs/real_data.md) with the command line's options.

    ``poses``, ``ranges`` (one or several) and ``anchors`` are paths, or DataFrames / mappings of columns
    with the files' columns (``ranges`` as DataFrames in memory: e.g. ``ab.simulate(...).ranges``). The
    result holds estimates.csv, ``summary`` (one row per trigger), ``replay_summary`` (a dict: the rows
    read, used and dropped, by reason and id), ``drops`` (a DataFrame), ``trace`` (``trace=True``: one row
    per range) and ``certificate_trace`` (``certificate_trace=True``: every evaluation of a solving
    trigger, why it waits). Dropped or reordered rows are also a ``ReplayWarning`` with the command
    line's summary (``warn=False``: kept in ``result.warnings`` only). With ``navigate``, also the
    navigation filter on the log with synthetic odometry (``replay --navigate``).
    """
    import tempfile

    if isinstance(ranges, (str, bytes, os.PathLike, Mapping)) or type(ranges).__name__ == "DataFrame":
        ranges = [ranges]
    options = dict(max_range_m=_in_range("max_range_m", max_range_m, 1e-3, 1e7),
                   average_poses_within_m=_in_range("average_poses_within_m", average_poses_within_m, 0.0, 10.0),
                   sort_window_s=_in_range("sort_window_s", sort_window_s, 0.0, 3600.0),
                   max_speed_mps=_in_range("max_speed_mps", max_speed_mps, 1e-3, 1e6))
    for name, value, allowed in (("repeated_poses", repeated_poses, ("error", "first", "average")),
                                 ("out_of_order", out_of_order, ("error", "drop", "sort"))):
        if value not in allowed:
            raise InputError(f"{name}: one of {', '.join(allowed)}, got {value!r}")
    loaded = None if config is None else load_config(config)
    with tempfile.TemporaryDirectory(prefix="anchorbench-replay-") as folder:
        files = [_log_file("poses", poses, folder)]
        files += [_log_file(f"ranges_{k}" if len(ranges) > 1 else "ranges", r, folder) for k, r in enumerate(ranges)]
        anchors_file = "" if anchors is None else _log_file("anchors", anchors, folder)
        # A DataFrame is named as its argument, its rows as the CSV's lines ("poses (DataFrame):2": row 0).
        written = {path: f"{os.path.basename(path)[:-4]} (DataFrame)" for path in files + [anchors_file]
                   if path.startswith(os.path.join(folder, ""))}
        try:
            files_ = _anchorbench._replay(files[0], files[1:], anchors_file, loaded, repeated_poses, out_of_order,
                                          bool(navigate), strict=bool(strict), trace=bool(trace),
                                          certificate_trace=bool(certificate_trace), **options)
        except InputError as error:
            text = str(error)
            for path, name in written.items():
                text = text.replace(path, name)
            for flag, argument in _REPLAY_FLAGS.items():
                text = text.replace(flag, argument)
            raise InputError(text) from None
        for path, name in written.items():
            files_._rename_input(path, name)
        result = Result(files_)
    if result.warnings and warn:
        import warnings

        warnings.warn(ReplayWarning("\n".join(result.warnings)), stacklevel=2)
    return result


def simulate(config: ConfigLike, realization: int = 0, *, seed: Optional[int] = None,
             overrides: Iterable[str] = ()) -> Result:
    """``anchorbench simulate``: one realization's poses, ranges and anchors (the truth)."""
    return Result(_anchorbench._simulate(_with(config, overrides, seed, None),
                                         _whole("realization", realization, 0, 100_000_000 - 1)))


class FrontEndWarning(UserWarning):
    """Ranges a FrontEnd could not place on their tag's poses (dropped; FrontEnd.counters has the counts)."""


class FrontEnd(_FrontEnd):
    """The online front end (estimator::FrontEnd) with a config's chains: one initializer per trigger and anchor.

    Feed poses and ranges one at a time (``add_pose``, ``add_range``, ``add_sample``) or as arrays
    (``add_poses``, ``add_ranges``, ``add_samples``), then ``take_events()``.
    """

    # Each tag's poses kept (estimator::PoseBufferOptions::history_s): a range older than its tag's
    # newest pose by more is dropped and counted. add_log feeds whole logs in windows well inside it.
    POSE_HISTORY_S = 30.0

    def __init__(self, config: ConfigLike = None, defer_solves: bool = False):
        super().__init__(None if config is None else load_config(config), bool(defer_solves))
        self._unplaced_warned = False

    def _warn_unplaced(self) -> None:
        """One FrontEndWarning, the first time ranges could not be placed on their tag's poses."""
        if self._unplaced_warned:
            return
        counters = self.counters
        lost = counters["ranges_outside_poses"] + counters["ranges_without_pose"]
        if lost:
            import warnings

            self._unplaced_warned = True
            warnings.warn(FrontEndWarning(
                f"{lost} range(s) could not be placed on their tag's poses and were dropped "
                f"({counters['ranges_outside_poses']} before the last {self.POSE_HISTORY_S:g} s of poses kept, "
                f"{counters['ranges_without_pose']} with no pose in time); feed poses and ranges in time order, or "
                f"whole logs with add_log(). FrontEnd.counters keeps the counts."), stacklevel=3)

    def add_log(self, pose_t_s, pose_tag_id, p_world_tag, range_t_s, range_tag_id, anchor_id, range_m,
                window_s: float = 10.0) -> None:
        """A whole log (all poses, all ranges, each in time order) fed in time windows: each window's
        ranges after the poses up to one window past them, so that none falls outside the poses kept."""
        import numpy as np

        window_s = _in_range("window_s", window_s, 1e-3, self.POSE_HISTORY_S / 3)
        pt = _floats("pose_t_s", pose_t_s, "(N,)")
        ptag = _ids("pose_tag_id", pose_tag_id, len(pt))
        p = _floats("p_world_tag", p_world_tag, "(N, 3)")
        rt = _floats("range_t_s", range_t_s, "(M,)")
        rtag, anchors = _ids("range_tag_id", range_tag_id, len(rt)), _ids("anchor_id", anchor_id, len(rt))
        d = _floats("range_m", range_m, "(M,)")
        for name, t in (("pose_t_s", pt), ("range_t_s", rt)):
            if t.ndim != 1 or np.any(np.diff(t) < 0):
                raise InputError(f"{name}: expected times in increasing order, shape (N,)")
        if len(pt) == 0 or len(rt) == 0:
            self.add_poses(pt, ptag, p)
            self.add_ranges(rt, rtag, anchors, d)
            return
        start = min(pt[0], rt[0])
        pose_at = range_at = 0
        for end in np.arange(start + window_s, max(pt[-1], rt[-1]) + 2 * window_s, window_s):
            pose_to = int(np.searchsorted(pt, end + window_s, side="left"))
            range_to = int(np.searchsorted(rt, end, side="left"))
            if pose_to > pose_at:
                self.add_poses(pt[pose_at:pose_to], ptag[pose_at:pose_to], p[pose_at:pose_to])
                pose_at = pose_to
            if range_to > range_at:
                self.add_ranges(rt[range_at:range_to], rtag[range_at:range_to], anchors[range_at:range_to],
                                d[range_at:range_to])
                range_at = range_to

    def add_pose(self, t_s: float, tag_id: int, p_world_tag) -> None:
        super().add_pose(_finite("t_s", t_s), _whole("tag_id", tag_id, -_MAX_ID - 1, _MAX_ID),
                         _point("p_world_tag", p_world_tag))

    def add_range(self, t_s: float, tag_id: int, anchor_id: int, range_m: float) -> None:
        super().add_range(_finite("t_s", t_s), _whole("tag_id", tag_id, -_MAX_ID - 1, _MAX_ID),
                          _whole("anchor_id", anchor_id, -_MAX_ID - 1, _MAX_ID), _finite("range_m", range_m))

    def add_sample(self, t_s: float, tag_id: int, anchor_id: int, range_m: float, p_world_tag) -> None:
        super().add_sample(_finite("t_s", t_s), _whole("tag_id", tag_id, -_MAX_ID - 1, _MAX_ID),
                           _whole("anchor_id", anchor_id, -_MAX_ID - 1, _MAX_ID), _finite("range_m", range_m),
                           _point("p_world_tag", p_world_tag))

    def add_poses(self, t_s, tag_id, p_world_tag) -> None:
        t = _floats("t_s", t_s, "(N,)")
        super().add_poses(t, _ids("tag_id", tag_id, len(t) if t.ndim == 1 else None),
                          _floats("p_world_tag", p_world_tag, "(N, 3)"))

    def add_ranges(self, t_s, tag_id, anchor_id, range_m) -> None:
        t = _floats("t_s", t_s, "(N,)")
        n = len(t) if t.ndim == 1 else None
        super().add_ranges(t, _ids("tag_id", tag_id, n), _ids("anchor_id", anchor_id, n),
                           _floats("range_m", range_m, "(N,)"))
        self._warn_unplaced()

    def add_samples(self, t_s, tag_id, anchor_id, range_m, p_world_tag) -> None:
        t = _floats("t_s", t_s, "(N,)")
        n = len(t) if t.ndim == 1 else None
        super().add_samples(t, _ids("tag_id", tag_id, n), _ids("anchor_id", anchor_id, n),
                            _floats("range_m", range_m, "(N,)"), _floats("p_world_tag", p_world_tag, "(N, 3)"))

    def take_events_frame(self):
        """The events since the last take as a DataFrame: anchor_id, trigger (its name), t_s, n_used,
        pdop_closest_point, x, y, z, bias_m, status (text)."""
        import pandas

        events = pandas.DataFrame(self.take_events_array())
        triggers = list(self.triggers)
        events.insert(1, "trigger", [triggers[c] for c in events.pop("chain")])
        events["status"] = events["status"].map(lambda b: b.decode() if isinstance(b, bytes) else b)
        return events

    def why_not_frame(self):
        """``why_not()`` as a DataFrame: one row per (anchor, trigger) still waiting, the test that holds it
        back (blocked_by), its value and limit, and the certificate's terms (NaN where none)."""
        import pandas

        return pandas.DataFrame(self.why_not())

    def run_pending_solves(self, max_count: Optional[int] = None, budget_s: float = 0.0) -> int:
        """Runs due solves (with defer_solves): at most max_count, none started after budget_s seconds (0: no limit)."""
        count = 2**63 - 1 if max_count is None else _whole("max_count", max_count, 0, 2**63 - 1)
        return super().run_pending_solves(count, _finite("budget_s", budget_s))

    def finish(self, t_end_s: float) -> None:
        super().finish(_finite("t_end_s", t_end_s))
        self._warn_unplaced()
