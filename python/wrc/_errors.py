"""The exceptions of wrc: each carries the engine's message (what is wrong, where, what was expected)."""


class Error(Exception):
    """An error of the engine: its message names the call, the key or the file and line, and what was expected."""


class OptionError(Error, ValueError):
    """A bad keyword argument: an unknown key (the message names the closest known one), a value out of range,
    a NaN, or a value of the wrong kind for its key."""


class ProfileError(Error):
    """A profile that cannot be loaded: a missing file, no reader for it, or bad content (file and line)."""


class NotConverged(Error):
    """A solve that did not converge. ``result`` is the partial result (its ``converged`` is False); pass
    ``on_failure="return"`` to get it returned instead of raised."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result

    def __str__(self):
        return self.args[0] if self.args else ""


class ProfileWarning(UserWarning):
    """What looks wrong in a loaded profile but was accepted: an orientation that looks reversed, points that scatter
    as measurement noise (the remedy named in the text). ``wrc.profile.load`` issues one per warning (also kept in
    ``p.warnings``); ``warnings.simplefilter("ignore", wrc.ProfileWarning)`` silences them."""


class ResolutionWarning(UserWarning):
    """A contact area spans too few elements of the grid for its peak pressure and area: a coarse grid gives a
    plausible-looking but wrong pmax (Hertzian contacts spanning 1-3 elements: up to 74 % off). Issued once per
    wheelset, naming the area and the grid that resolves it; each area's ``resolved`` says it every time."""
