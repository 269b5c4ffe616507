# pytest from anywhere in the tree: the package (python/) and the module CMake built
# (build/python/) on the path, and the plugin loaded (docs/python.md). An installed package
# registers the same plugin under the same name, so it is loaded once either way.
import os
import sys

_here = os.path.dirname(os.path.abspath(__file__))
# Under ctest (UPROG names the build's uprog), PYTHONPATH already holds the module of the build
# being tested, or none (the sanitizer build makes none): the tree's build/python would mix
# another build's module in.
_paths = [os.path.join(_here, "python")]
if not os.environ.get("UPROG"):
    _paths.insert(0, os.path.join(_here, "build", "python"))
for _path in _paths:
    if os.path.isdir(_path) and _path not in sys.path:
        sys.path.insert(0, _path)

pytest_plugins = ["uprog.pytest_plugin"]
