"""Reading the JSON table a `planet lab` command wrote, for its report."""

import json
import os
import sys


def load_table(out, file_name, keys, program, what):
    """OUT/FILE_NAME as JSON; exits with one line naming the file where it
    cannot be read or lacks one of KEYS (then it is not WHAT)."""
    path = os.path.join(out, file_name)
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"{program}: {path}: {e}")
    for key in keys:
        if key not in doc:
            sys.exit(f"{program}: {path}: no '{key}': not {what}")
    return doc
