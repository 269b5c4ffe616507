# pytest from anywhere in the tree: the package (python/) and the module CMake built
# (build/python/) on the path, and the plugin loaded (docs/python.md). An installed package
# registers the same plugin under the same name, so it is loaded once either way.
import os
import sys

_here = os.path.dirname(os.path.abspath(__file__))
for _path in (os.path.join(_here, "build", "python"), os.path.join(_here, "python")):
    if os.path.isdir(_path) and _path not in sys.path:
        sys.path.insert(0, _path)

pytest_plugins = ["uprog.pytest_plugin"]
