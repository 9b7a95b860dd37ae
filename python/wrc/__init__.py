"""wrc: wheel-rail contact (Baeza et al. 2018) from Python, with the Lua API's names and keys.

    import wrc
    ws = wrc.wheelset(wheel=wrc.profile.load("profiles/s1002.lua"), rail=wrc.profile.load("profiles/60e1.lua"))
    e = ws.equilibrium(y=3e-3, Q=200e3)
    print(e.Y_Q, e.left.patches[0].pmax)

Every call takes the keys of its Lua twin as keyword arguments (SI units); help(wrc.wheelset),
help(wrc.Wheelset.contact), ... list them with unit, default and meaning (from the engine's one description of its
options, also in wrc.operations()). Results are wrc.Result objects with the Lua field names (lists 0-based), arrays
and grids numpy arrays, tables pandas DataFrames. Errors: wrc.Error and its subclasses (wrc.OptionError,
wrc.NotConverged, wrc.ProfileError); what looks wrong in a loaded profile is a wrc.ProfileWarning, a contact area
too narrow for its grid a wrc.ResolutionWarning. docs/python.md is the guide.
"""

import sys as _sys

from wrc._errors import Error, NotConverged, OptionError, ProfileError, ProfileWarning, ResolutionWarning
from wrc._results import Result
from wrc import _wrc
from wrc._wrc import Profile, Trajectory, Wheelset, batch_keys, conicity as _conicity, operations, profile, wheelset
from wrc.batch import Batch

__version__ = _wrc.__version__
_sys.modules[__name__ + ".profile"] = profile  # import wrc.profile works too

__all__ = [
    "Batch", "Error", "NotConverged", "OptionError", "ProfileError", "ProfileWarning", "ResolutionWarning", "Result",
    "Profile", "Trajectory", "Wheelset",
    "batch_keys", "conicity", "operations", "profile", "wheelset",
]


def _table_columns(table):
    """A DataFrame's columns by their names without the unit ("y [m]" -> "y"), as the engine's keys."""
    try:
        import pandas as pd
    except ImportError:  # pragma: no cover - pandas is a dependency of the tables only
        return table
    if isinstance(table, pd.DataFrame):
        return {str(c).split(" [", 1)[0]: table[c].to_numpy() for c in table.columns}
    return table


def conicity(table=None, **options):
    return _conicity(_table_columns(table), **options)


conicity.__doc__ = _conicity.__doc__
