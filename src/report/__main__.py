# Entry point when the directory is run (`/usr/bin/python3 -B -E -s src/report RESULT.h5 [--out DIR]`):
# the directory is sys.path[0], so the package beside this file is imported. Prints one line and exits
# 3 when the package or its libraries cannot be imported; never a traceback.
import sys

try:
    from pbrfit_report.command import main
except Exception as error:  # noqa: BLE001 - anything here means the report cannot run at all
    print(f"pbrfit: error: the report cannot start: {type(error).__name__}: {error}".replace("\n", "\\n"),
          file=sys.stderr)
    sys.exit(3)

sys.exit(main(sys.argv[1:]))
