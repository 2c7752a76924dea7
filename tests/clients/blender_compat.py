# What Debian 12's Blender 3.4 needs on its Python 3.11 and numpy 1.24, imported
# first by every script the client tests run in Blender (one place for both):
# its BVH importer opens files in mode 'rU', which Python 3.11 refuses; its glTF
# importer calls numpy.bool, which numpy 1.24 removed (every glTF mesh import fails).
import builtins

import numpy

_open = builtins.open
builtins.open = lambda file, mode="r", *a, **k: _open(file, mode.replace("U", ""), *a, **k)
if not hasattr(numpy, "bool"):
    numpy.bool = bool
