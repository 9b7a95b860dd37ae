"""The package imports from the build tree, and its module, errors and help are there."""
import wrc


def test_import_names():
    for name in ("wheelset", "conicity", "profile", "Profile", "Wheelset", "Trajectory", "Result", "Error",
                 "OptionError", "NotConverged", "ProfileError", "operations"):
        assert hasattr(wrc, name), name
    assert issubclass(wrc.OptionError, ValueError) and issubclass(wrc.OptionError, wrc.Error)
    assert issubclass(wrc.NotConverged, wrc.Error) and issubclass(wrc.ProfileError, wrc.Error)
    import wrc.profile as p

    assert p.load is wrc.profile.load


def test_equilibrium_runs(ws):
    e = ws.equilibrium(y=3e-3, Q=200e3)
    assert e.converged
    assert e.left.patches[0].pmax > 0
