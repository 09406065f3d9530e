"""Python functions as curvebench algorithms.

A function ``f(points) -> edges`` (or ``-> (edges, points)`` for one that moves or drops
points) becomes a *session algorithm* of the registry (algorithms/registry.h): the verbs
find it by its name as they find a built-in one. Its calls come back here, to
``Algorithm._invoke``, which calls the function and checks what it returned.
"""
import re

import numpy as np

from . import _curvebench as _core
from ._curvebench import InvalidOutput

_NAME_CHARACTERS = re.compile(r"[^a-z0-9_.-]+")

# Every Algorithm made in this session, by name and by the id of the function it was made
# of (any callable will do, hashable or not; _functions keeps each alive, so no id is reused).
_by_name = {}
_by_function = {}
_functions = []


def _parameter_rows(parameters):
    """The registry's parameter rows of ``parameters``: {name: default}, {name: (default,
    minimum, maximum)} or {name: {"default": ..., "minimum": ..., "maximum": ..., "type":
    "real" or "integer", "meaning": ...}}."""
    rows = []
    for name, spec in (parameters or {}).items():
        if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
            raise ValueError(f"a parameter's name is a Python identifier, not {name!r}")
        if isinstance(spec, dict):
            unknown = set(spec) - {"default", "minimum", "maximum", "type", "meaning"}
            if unknown:
                raise ValueError(f"parameter {name}: unknown keys {sorted(unknown)}")
            default, minimum, maximum = spec.get("default"), spec.get("minimum", -np.inf), spec.get("maximum", np.inf)
            kind, meaning = spec.get("type"), spec.get("meaning", "")
        elif isinstance(spec, (tuple, list)):
            if len(spec) != 3:
                raise ValueError(f"parameter {name}: (default, minimum, maximum), not {spec!r}")
            (default, minimum, maximum), kind, meaning = spec, None, ""
        else:
            default, minimum, maximum, kind, meaning = spec, -np.inf, np.inf, None, ""
        for what, value in (("default", default), ("minimum", minimum), ("maximum", maximum)):
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
                raise ValueError(f"parameter {name}: its {what} is a number, not {value!r}")
        if kind is None:  # whole numbers throughout: an integer parameter
            whole = [isinstance(v, (int, np.integer)) or not np.isfinite(v) for v in (minimum, maximum)]
            kind = "integer" if isinstance(default, (int, np.integer)) and all(whole) else "real"
        if kind not in ("real", "integer"):
            raise ValueError(f"parameter {name}: its type is real or integer, not {kind!r}")
        rows.append({"name": name, "type": kind, "default": float(default), "minimum": float(minimum),
                     "maximum": float(maximum), "meaning": str(meaning)})
    return rows


def _edge_like(value):
    try:
        return np.ndim(value) == 2 or len(value) == 0
    except (TypeError, ValueError):
        return False


def _checked_result(result, count):
    """(edges as an (m, 2) int64 array, points as an (k, 2) float64 array or None) of what
    a function returned for ``count`` points; InvalidOutput if it is not edges between them."""
    points = None
    if isinstance(result, tuple) and len(result) == 2 and _edge_like(result[0]):
        result, given = result
        try:
            points = np.asarray(given, dtype=np.float64)
        except (TypeError, ValueError) as error:
            raise InvalidOutput(f"points: not an array of numbers ({error})") from None
        if points.ndim != 2 or points.shape[1] != 2:
            raise InvalidOutput(f"points: an (n, 2) array, not shape {points.shape}")
        finite = np.isfinite(points).all(axis=1)
        if not finite.all():
            raise InvalidOutput(f"points: point {int(np.argmin(finite))} has a non-finite coordinate")
        points = np.ascontiguousarray(points)
        count = len(points)
    if result is None:
        raise InvalidOutput("the algorithm returned None, not edges")
    if isinstance(result, (set, frozenset)) or (not hasattr(result, "__len__") and hasattr(result, "__iter__")):
        result = sorted(result) if isinstance(result, (set, frozenset)) else list(result)  # a set or generator of pairs
    try:
        edges = np.asarray(result)
    except (TypeError, ValueError) as error:
        raise InvalidOutput(f"edges: not an array of indices ({error})") from None
    if edges.size == 0:
        return np.empty((0, 2), dtype=np.int64), points
    if edges.dtype.kind not in "iu":
        raise InvalidOutput(f"edges: integer indices, not dtype {edges.dtype}")
    if edges.ndim != 2 or edges.shape[1] != 2:
        raise InvalidOutput(f"edges: an (m, 2) array of indices, not shape {edges.shape}")
    outside = (edges >= count) | (edges < 0) if edges.dtype.kind == "i" else edges >= count
    if outside.any():
        k = int(np.argmax(outside.any(axis=1)))
        index = edges[k][outside[k]][0]
        raise InvalidOutput(f"edges[{k}]: index {index} out of range ({count} points)")
    edges = np.ascontiguousarray(edges, dtype=np.int64)
    loops = edges[:, 0] == edges[:, 1]
    if loops.any():
        k = int(np.argmax(loops))
        raise InvalidOutput(f"edges[{k}]: a self-loop at {edges[k, 0]}")
    return edges, points


class Algorithm:
    """A Python function as a curvebench algorithm, made by :func:`curvebench.algorithm`.

    Calling it calls the function itself; ``name`` is what every curvebench function
    knows it by. ``function`` may be replaced by :func:`curvebench.algorithm` with the same
    name and description (a notebook cell run again)."""

    def __init__(self, function, name, description):
        self.function = function
        self.name = name
        self._description = description

    def __call__(self, *args, **kwargs):
        return self.function(*args, **kwargs)

    def __repr__(self):
        return f"<curvebench.Algorithm {self.name!r} of {getattr(self.function, '__qualname__', self.function)!r}>"

    def _invoke(self, points, parameters):
        """Called by the registry (python/src/python_algorithm.cpp), the GIL held."""
        return _checked_result(self.function(points, **parameters), len(points))


def _free_name(function):
    """A name for a function given none: its own, lowercased, then .2, .3, ... while taken."""
    base = getattr(function, "__name__", type(function).__name__).lower()
    base = _NAME_CHARACTERS.sub("-", base).strip("-_.") or "python"
    name, k = base, 1
    while name in _by_name or _core.algorithm_exists(name):
        k += 1
        name = f"{base}.{k}"
    return name


def algorithm(function=None, *, name=None, title=None, parameters=None, epsilon_below=None, rho_below=None,
              uniformity_below=None, covers_open_curves=False, condition=None, capabilities=None):
    """Makes ``function`` a curvebench algorithm; usable as a decorator, with or without arguments."""
    def make(f):
        if isinstance(f, Algorithm):
            return f
        if not callable(f):
            raise TypeError(f"an algorithm is a function, not {f!r}")
        description = {
            "title": title,
            "parameters": _parameter_rows(parameters),
            "condition": {"statement": condition or _statement(epsilon_below, rho_below, uniformity_below),
                          "epsilon_below": _bound(epsilon_below, "epsilon_below"),
                          "rho_below": _bound(rho_below, "rho_below"),
                          "uniformity_below": _bound(uniformity_below, "uniformity_below"),
                          "covers_open_curves": bool(covers_open_curves)},
            "capabilities": dict(capabilities or {}),
        }
        if name is None:
            made = _by_function.get(id(f))
            if made is not None and made._description == description:
                return made
            chosen = _free_name(f)
        else:
            chosen = name
            made = _by_name.get(chosen)
            if made is not None:
                if made._description != description:
                    raise ValueError(f"the algorithm '{chosen}' is taken, by another description")
                made.function = f  # the same algorithm, its function defined again
                _by_function[id(f)] = made
                _functions.append(f)
                return made
        made = Algorithm(f, chosen, description)
        caps = {k: (("yes" if v else "no") if isinstance(v, bool) else v) for k, v in description["capabilities"].items()}
        if "guarantee" in caps:
            caps["guarantee"] = caps["guarantee"] in ("yes", True)
        _core.add_algorithm(chosen, made._invoke, title or getattr(f, "__qualname__", chosen),
                            description["parameters"], description["condition"], caps)
        _by_name[chosen] = made
        _by_function[id(f)] = made
        _functions.append(f)
        return made

    return make(function) if function is not None else make


def _bound(value, what):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) or not value > 0:
        raise ValueError(f"{what} is a positive number, not {value!r}")
    return float(value)


def _statement(epsilon_below, rho_below, uniformity_below):
    parts = [f"{what} < {value:g}" for what, value in
             (("epsilon", epsilon_below), ("rho", rho_below), ("uniformity", uniformity_below)) if value is not None]
    return " and ".join(parts) if parts else "none declared"


def as_name(given):
    """The name under which ``given`` (a name, an Algorithm, any callable) runs."""
    if isinstance(given, str):
        return given
    if isinstance(given, Algorithm):
        return given.name
    if callable(given):
        made = _by_function.get(id(given))
        return made.name if made is not None else algorithm(given).name
    raise TypeError(f"an algorithm is a name or a function, not {given!r}")
