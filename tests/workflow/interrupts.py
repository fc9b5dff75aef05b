"""What the workflow tests share to interrupt a tool deterministically (imported by
test_grade.py and test_gallery.py, which ctest runs as scripts: their folder is on sys.path)."""

# A tool run through runpy with a Ctrl-C landing just after a temporary file (NAME.tmp) is
# renamed to its output, before the tool says what it wrote: argv[1] is the tool's script, the
# rest its arguments. Run as `python3 -c INTERRUPTED_AFTER_WRITING SCRIPT ARG...`.
INTERRUPTED_AFTER_WRITING = """\
import os, runpy, sys
replace = os.replace
def replace_then_interrupt(src, dst, **kwargs):
    replace(src, dst, **kwargs)
    if os.fspath(src).endswith(".tmp"):
        raise KeyboardInterrupt
os.replace = replace_then_interrupt
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""
