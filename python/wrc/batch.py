"""Batch calls: ws.contact, ws.wheel, ws.equilibrium and ws.rigid with arrays for number arguments.

Any argument of type "number" of the operation (the pose, the loads, the creepages, speeds, friction, tolerances:
``wrc.batch_keys(op)`` lists them, from the engine's option table) may be a numpy array or a list; the arrays
broadcast together (numpy's rules) to the batch shape, and each element is one call, solved on worker threads
(``threads=``, default all cores) with the GIL released. The result is a :class:`Batch`.

Each element's result equals the same call made alone, bit for bit: elements are read from their own options and
start cold (the engine's per-thread workspace forgets the element before), whatever the thread count or order.
"""
import numbers

import numpy as np

__all__ = ["Batch", "BatchList", "BatchNode", "split_batch"]


def _is_array(v):
    return isinstance(v, (list, tuple)) or getattr(v, "ndim", 0) > 0  # numpy arrays, pandas Series


def _column(context, key, value):
    try:
        a = np.asarray(value)
    except ValueError as e:  # a ragged list
        raise TypeError(f"{context}: '{key}' must be a number or an array of numbers ({e})") from None
    if a.dtype.kind not in "iuf":
        raise TypeError(f"{context}: '{key}' must be a number or an array of numbers, got an array of {a.dtype}")
    if np.ma.is_masked(value):  # np.asarray keeps the values behind the mask: the elements masked out would be solved
        raise TypeError(f"{context}: '{key}' is a masked array with {np.ma.count_masked(value)} masked value(s): "
                        "give the values to solve (a masked value has no number to solve for)")
    return a.astype(np.float64, copy=False)


def split_batch(context, kwargs, batch_keys, option_error):
    """Splits keyword arguments into the shared options and the batch's columns.

    Returns None when no batchable argument is an array (a one-by-one call), else (shared, keys, columns, shape):
    `shared` the arguments without the columns, `keys` the columns' keys ("creepage.xi" for a nested one),
    `columns` float64 arrays of the broadcast shape (read-only views: the engine copies them once it has checked that
    the batch fits its memory), `shape` the broadcast shape.
    """
    batchable = set(batch_keys)
    shared, keys, arrays = dict(kwargs), [], []
    for key, value in kwargs.items():
        if isinstance(value, dict):  # a nested table: creepage = {xi = ...}
            inner = dict(value)
            for k, v in value.items():
                if f"{key}.{k}" in batchable and _is_array(v):
                    keys.append(f"{key}.{k}")
                    arrays.append(_column(context, f"{key}.{k}", v))
                    del inner[k]
            shared[key] = inner
        elif key in batchable and _is_array(value):
            keys.append(key)
            arrays.append(_column(context, key, value))
            del shared[key]
    if not keys:
        return None
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError:
        listed = ", ".join(f"{k} {a.shape}" for k, a in zip(keys, arrays))
        raise option_error(f"{context}: the batch's arrays do not broadcast together: {listed}") from None
    columns = [np.broadcast_to(a, shape) for a in arrays]
    return shared, keys, columns, shape


# ---- the result: fields stacked over the batch ----
#
# The elements' results stay in the engine's form (a wrc._wrc._BatchNodes: one node per element, engine/src/python/
# batch_fields.cpp), which stacks a field into one array when it is first read; each element's wrc.Result is made
# only when Batch.items is first read.

_MISSING = object()


def _nodes_from(state):
    """The engine's results of a batch from what pickling them gave (wrc._wrc._BatchNodes.__reduce__)."""
    from wrc import _wrc

    return _wrc._batch_nodes(state)


def _stack(got, shape):
    """A BatchNode, BatchList or array of the batch's shape from what _BatchNodes.field gives, or _MISSING when the
    field does not stack (arrays, grids, values of different kinds)."""
    if got is None:
        return _MISSING
    if isinstance(got, np.ndarray):
        return got.reshape(shape)
    return BatchList(got, shape) if got.is_list else BatchNode(got, shape)


class BatchNode:
    """A table of the results stacked over the batch: its fields are arrays of the batch's shape (or nested nodes
    and lists), in the order the results give them."""

    def __init__(self, nodes, shape):
        self._nodes, self._shape, self._cache = nodes, tuple(shape), {}
        self._keys = nodes.keys()

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        if name not in self._cache:
            if name not in self._keys:
                raise AttributeError(f"no field '{name}' in the batch's results (fields: {', '.join(self._keys)})")
            self._cache[name] = _stack(self._nodes.field(name), self._shape)
        got = self._cache[name]
        if got is _MISSING:
            raise AttributeError(f"the field '{name}' does not stack over the batch (arrays and grids of each "
                                 "element are in Batch.items)")
        return got

    def __getitem__(self, name):
        if not isinstance(name, str):  # b[0] meant an element: said so, not "'int' object has no attribute ..."
            raise TypeError(f"a batch's fields are indexed by name (b['z'], b.z), got {type(name).__name__}: an "
                            "element's whole result is b.items[index], a field's value there b.z[index]")
        return self.__getattr__(name)

    def __contains__(self, name):
        return name in self.keys()

    def __iter__(self):  # without it Python iterates by b[0], b[1], ...
        raise TypeError("a batch is not iterable: b.keys() lists its fields, b.items holds its elements' results")

    def keys(self):
        """The fields that stack over the batch."""
        return [k for k in self._keys if self._stacks(k)]

    def _stacks(self, k):
        try:
            self.__getattr__(k)
            return True
        except AttributeError:
            return False

    def to_dict(self):
        out = {}
        for k in self.keys():
            v = self.__getattr__(k)
            out[k] = v.to_dict() if isinstance(v, (BatchNode, BatchList)) else v
        return out

    def __dir__(self):
        return list(super().__dir__()) + self.keys()

    def __reduce__(self):
        # pickle and copy: the engine's results it reads (they pickle bit for bit), not the arrays made from them
        return type(self), (self._nodes, self._shape)

    def __repr__(self):
        return f"<wrc batch fields, shape {self._shape}: {', '.join(self.keys())}>"


class BatchList:
    """A list field (e.g. patches) over the batch, padded to the longest: ``count`` is each element's length (int64
    array of the batch's shape; 0 for a failed element), ``b.patches[k]`` the k-th items as a node of arrays of the
    batch's shape (NaN where an element has fewer than k + 1), and ``b.patches.pmax`` the field of every item as an
    array of shape batch shape + (longest,), NaN-padded."""

    def __init__(self, nodes, shape):
        self._nodes, self._shape = nodes, shape
        self.count = nodes.counts().reshape(shape)
        self._longest = int(self.count.max()) if self.count.size else 0
        self._items = {}
        self._padded = None

    def __len__(self):
        return self._longest

    def __getitem__(self, k):
        if not isinstance(k, numbers.Integral):
            raise TypeError("a batch list is indexed by an item number (0-based)")
        if k < 0:
            k += self._longest
        if not 0 <= k < self._longest:
            raise IndexError(f"item {k} of a list whose longest has {self._longest} items")
        if k not in self._items:
            self._items[k] = BatchNode(self._nodes.item(k), self._shape)
        return self._items[k]

    def __iter__(self):
        return (self[k] for k in range(self._longest))

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        if self._padded is None:  # items along a last axis
            self._padded = BatchNode(self._nodes.padded(self._longest), tuple(self._shape) + (self._longest,))
        return getattr(self._padded, name)

    def to_dict(self):
        return {"count": self.count, "items": [self[k].to_dict() for k in range(self._longest)]}

    def __reduce__(self):
        return BatchList, (self._nodes, self._shape)

    def __repr__(self):
        return f"<wrc batch list, shape {self._shape}, longest {self._longest}>"


class Batch(BatchNode):
    """The result of a batch call.

    Fields: every numeric field of the results, as an array of the batch's shape (``b.force.y``, ``b.converged``):
    float64 with NaN where an element failed or has no such field; int64 and bool arrays when every element has the
    field, float64 with NaN otherwise. Strings are object arrays (None where absent). List fields (patches) are
    :class:`BatchList` (padded with NaN to the longest, with ``count``). Arrays and grids of each element are in
    ``items`` only. A field's array is made when the field is first read, from the engine's results.

    Also: ``shape``, ``size``, ``ok`` (bool array: the element has a result in the arrays), ``items`` (object array
    of the batch's shape: each element's wrc.Result, None where it failed; made when first read), ``errors`` (list
    of the failed elements' exceptions, each with ``.index``, its index into the batch: wrc.Error, or
    wrc.NotConverged with ``.result``), ``threads`` (worker threads run), ``seconds`` (wall time of the solves).

    A batch pickles (a process pool returns it, a file keeps it) and copies (copy.copy, copy.deepcopy): the copy
    holds every element's result bit for bit, its errors, shape, threads and seconds.
    """

    def __init__(self, operation, shape, nodes, errors, threads, seconds):
        super().__init__(nodes, shape)
        self.operation = operation
        self.shape = tuple(shape)
        self.size = len(nodes)
        self.ok = nodes.present().reshape(self.shape)
        self.errors = errors
        self.threads = threads
        self.seconds = seconds
        self._items_made = None

    @property
    def items(self):
        """Each element's wrc.Result (None where it failed), an object array of the batch's shape: made from the
        engine's results when first read, the same objects afterwards."""
        if self._items_made is None:
            items = np.empty(self.size, dtype=object)
            items[:] = self._nodes.results()
            self._items_made = items.reshape(self.shape)
        return self._items_made

    def __len__(self):
        return self.shape[0] if self.shape else 1

    def __reduce__(self):
        # pickle (a process pool, a file) and copy.copy / deepcopy: the engine's results -- each element's recorded
        # result, written and read back bit for bit -- the errors (exceptions pickle with .index and .result) and the
        # run's figures. The arrays and items read so far are not written: the copy makes them again when read.
        state = {"threads_note": self.threads_note} if "threads_note" in self.__dict__ else None
        return Batch, (self.operation, self.shape, self._nodes, self.errors, self.threads, self.seconds), state

    def __repr__(self):
        return (f"<wrc.Batch {self.operation}, shape {self.shape}, {len(self.errors)} failed, "
                f"{self.threads} threads, {self.seconds:.3g} s>")
