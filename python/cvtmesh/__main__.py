"""`python3 -m cvtmesh`: what the package holds and how to run its tools."""

import sys

from . import __version__


def main() -> int:
    print(f"cvtmesh {__version__} (Python module)\n"
          "  python3 -m cvtmesh.report IN OUT -o report.html   a page comparing a mesh and its remesh\n"
          "  python3 -m cvtmesh.batch IN_DIR OUT_DIR --vertices N   remesh a folder of meshes\n"
          "  python3 -c 'import cvtmesh; help(cvtmesh)'          the API")
    return 0


if __name__ == "__main__":
    sys.exit(main())
