"""Every report script's outputs checked against its inputs before anything is written: an
output that is an input, however spelled (the same file by device and inode, so a symbolic link
or a hard link to it counts; by resolved path when the output does not exist yet), or another
output, is bad input (exit 2, naming both), and nothing is changed. Standard library only.
"""

import os

from agvreports.report_io import ReportError


def _identity(path):
    """(device, inode) of the file `path` names, symbolic links followed; its resolved path when
    it does not exist (yet)."""
    try:
        st = os.stat(path)
        return ("inode", st.st_dev, st.st_ino)
    except OSError:
        return ("path", os.path.realpath(path))


def check_outputs(outputs, inputs):
    """`outputs` and `inputs` are lists of (what, path), e.g. ("--out", "CLAIMS.md") and
    ("report", "r.json"). Raises ReportError at the first output that is an input or an earlier
    output; an output that is an existing folder is refused too."""
    seen = [(what, path, _identity(path)) for what, path in inputs]
    for what, path in outputs:
        if os.path.isdir(path):
            raise ReportError(f"{what} {path}: is a folder, expected a file to write")
        ident = _identity(path)
        for other_what, other_path, other in seen:
            if ident == other:
                raise ReportError(f"{what} {path}: is the {other_what} {other_path} (the same file): "
                                  "an output never replaces what the script reads or writes")
        seen.append((what, path, ident))


def check_output_folder(what, folder, names, inputs):
    """A folder the script writes files into: it must be a folder (or not exist yet), and no
    file in it that the script may write (`names(entry)` true) may be one of `inputs`."""
    if os.path.exists(folder) and not os.path.isdir(folder):
        raise ReportError(f"{what} {folder}: is a file, expected a folder for the outputs")
    if not os.path.isdir(folder):
        return
    try:
        entries = sorted(e for e in os.listdir(folder) if names(e))
    except OSError as e:
        raise ReportError(f"{what} {folder}: cannot list it: {e.strerror}") from None
    check_outputs([(what, os.path.join(folder, e)) for e in entries], inputs)
