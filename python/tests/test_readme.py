# SPDX-License-Identifier: GPL-3.0-or-later
"""The README's Python example, run as a user would after scripts/run_default.sh: the
printed line must be the one the README shows in its comment."""
import contextlib
import io
import os
import re

README = os.path.join(os.path.dirname(__file__), "..", "..", "README.md")


def readme_python_example():
    text = open(README, encoding="utf-8").read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 1, "the README has one Python example"
    return blocks[0]


def test_readme_python_example_prints_what_it_says():
    code = readme_python_example()
    # the README's paths are those of a build in ./build; the test's build is FS_BINARY_DIR
    code = code.replace('"build/data/meshes/', '"' + os.environ["FS_MESH_DIR"] + "/")
    printed = [line for line in code.splitlines() if line.startswith("print(")]
    assert len(printed) == 1 and "#" in printed[0], "one print line, its output in a comment"
    expected = printed[0].split("#", 1)[1].strip()
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "README.md", "exec"), {})
    assert out.getvalue().strip() == expected
