"""Results as Python objects: the engine describes each result field by field (with its unit); the compiled module
turns a table into a Result, a list into a list, an array into a numpy array and a grid into a 2-D numpy array of
shape (ny, nx)."""

from collections.abc import Mapping

import numpy as np


class Result(Mapping):
    """A result table: fields by attribute (``r.force.y``) or by key (``r["force"]``), the names of the Lua API.

    ``keys()`` lists the fields in the order the engine describes them, ``units`` gives each field's SI unit
    ("-" for pure numbers), ``to_dict()`` the plain nested dicts."""

    __slots__ = ("_data", "_unit_data", "_node")

    def __init__(self, fields, units=None):
        # The module hands over dicts of its own: kept, not copied (a batch makes hundreds of Results per element).
        object.__setattr__(self, "_node", None)
        object.__setattr__(self, "_data", fields if type(fields) is dict else dict(fields))
        object.__setattr__(self, "_unit_data", units if type(units) is dict else dict(units or {}))
        self._add_grid_coordinates()

    @classmethod
    def _deferred(cls, node):
        """A Result whose fields the compiled module makes when first read, from `node` (the engine's recorded result
        table, kept by the node): a call's result then costs only the fields the caller reads (a wheel solve
        describes ~200 tables and ~190 arrays)."""
        r = object.__new__(cls)
        object.__setattr__(r, "_node", node)
        object.__setattr__(r, "_data", None)
        object.__setattr__(r, "_unit_data", None)
        return r

    def _expand(self):
        node = self._node
        if node is None:  # made meanwhile by another thread
            return
        fields, units = node.expand()
        object.__setattr__(self, "_data", fields)
        object.__setattr__(self, "_unit_data", units)
        object.__setattr__(self, "_node", None)
        self._add_grid_coordinates()

    @property
    def _fields(self):
        if self._data is None:
            self._expand()
        return self._data

    @property
    def _units(self):
        if self._unit_data is None:
            self._expand()
        return self._unit_data

    def _add_grid_coordinates(self):
        grid = self._data.get("grid")
        if type(grid) is Result and {"nx", "ny", "dx", "dy", "x0", "y0"} <= grid._fields.keys():
            # The coordinates of the element centres: u along t1 (x, rolling), v along t2 (y, lateral), as
            # frame.origin + u t1 + v t2 (the result's own grid description; grids are (ny, nx): row j is v[j]).
            grid._fields.setdefault("x", grid.x0 + grid.dx * np.arange(grid.nx))
            grid._fields.setdefault("y", grid.y0 + grid.dy * np.arange(grid.ny))
            grid._units.setdefault("x", "m")
            grid._units.setdefault("y", "m")

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self._fields[name]
        except KeyError:
            raise AttributeError(f"the result has no field '{name}' (fields: {', '.join(self._fields)})") from None

    def __setattr__(self, name, value):
        raise AttributeError("a wrc.Result is read-only")

    def __getitem__(self, key):
        return self._fields[key]

    def __iter__(self):
        return iter(self._fields)

    def __len__(self):
        return len(self._fields)

    def __dir__(self):
        return list(self._fields) + ["keys", "units", "to_dict"]

    def __reduce__(self):
        # pickle (multiprocessing, saving results) and copy: the fields themselves, a deferred table expanded (the
        # engine's record of it is not Python data); __setattr__ refuses the default way of restoring a Result.
        return Result, (dict(self._fields), dict(self._units))

    @property
    def units(self):
        """Each field's unit ("m", "N", "Pa", "rad", "-"), by name; fields without one (text, flags, tables) absent."""
        return dict(self._units)

    def to_dict(self):
        """The result as nested dicts and lists (arrays stay numpy arrays)."""
        return {k: _plain(v) for k, v in self._fields.items()}

    def __repr__(self):
        parts = []
        for k, v in self._fields.items():
            if isinstance(v, (Result, list, np.ndarray)):
                parts.append(f"{k}=<{_shape(v)}>")
            else:
                parts.append(f"{k}={v!r}")
            if len(parts) == 8 and len(self._fields) > 8:
                parts.append("...")
                break
        return "Result(" + ", ".join(parts) + ")"


def _plain(v):
    if isinstance(v, Result):
        return v.to_dict()
    if isinstance(v, list):
        return [_plain(x) for x in v]
    return v


def _shape(v):
    if isinstance(v, Result):
        return f"Result with {len(v)} fields"
    if isinstance(v, list):
        return f"list of {len(v)}"
    return f"array {v.shape}"


def _flatten(result, prefix, out):
    """The scalar fields of a result, nested tables as 'left.force.z', each named with its unit: 'Y [N]'."""
    for k, v in result._fields.items():
        name = prefix + k
        if isinstance(v, Result):
            _flatten(v, name + ".", out)
        elif isinstance(v, (bool, int, float, str)):
            unit = result._units.get(k, "")
            out[f"{name} [{unit}]" if unit and unit != "-" else name] = v


def frame(rows):
    """A pandas DataFrame of results: one row per result, one column per scalar field (lists and arrays left out:
    they stay in the results), units in the column names ("y [m]", "left.force.z [N]")."""
    import pandas as pd

    records = []
    for r in rows:
        flat = {}
        _flatten(r, "", flat)
        records.append(flat)
    return pd.DataFrame.from_records(records)


def with_table(result, key):
    """The result with `table`: frame(result[key])."""
    fields = dict(result._fields)
    fields["table"] = frame(result[key])
    return Result(fields, result._units)


def rows_frame(result, key):
    """frame(result[key]), the result's other fields in the DataFrame's attrs (e.g. a geometry table's jumps)."""
    df = frame(result[key])
    df.attrs.update({k: v for k, v in result._fields.items() if k != key})
    return df
