"""garotor: rigid motions in conformal geometric algebra G(4,1), vectorised
over numpy arrays (docs/python.md).

The calls, Path, Multivector and the rest are the C extension's
(garotor._garotor); garotor.dask (imported on its own: it needs dask) runs
them on dask arrays and bags (docs/python.md, "Beyond one machine").
"""
from ._garotor import *  # noqa: F401,F403 (every public name of the extension)
from ._garotor import __version__ as __version__  # the C library's version (meson.build)
