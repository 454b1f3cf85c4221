"""bearing: the rolling-bearing vibration toolkit from Python.

``bearing.plot`` (figures of runs, sweeps and FE contact outputs) is pure Python (NumPy,
matplotlib) and works without the compiled extension ``_bearing``; the rest of the package needs it.
"""
try:
    from . import _bearing  # noqa: F401
except ImportError:  # the .py files are there but the extension was not built
    _bearing = None
