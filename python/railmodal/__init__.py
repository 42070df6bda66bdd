"""railmodal: modal and frequency-response analysis of railway vehicles, from Python.

The compiled extension ``railmodal._railmodal`` wraps the C++ library; this package re-exports
it, with vehicle_from_dict beside it. docs/python.md is the guide.
"""
from ._railmodal import *  # noqa: F401,F403
from ._railmodal import __version__  # noqa: F401
from .vehicle_dict import vehicle_from_dict  # noqa: F401
