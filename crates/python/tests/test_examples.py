"""The examples in the type stubs and the package docstring run and print what they show, and
the stubs describe exactly the public API."""

from __future__ import annotations

import ast
import doctest
from pathlib import Path

import numpy as np

import surftopo

STUBS = Path(surftopo.__file__).with_name("__init__.pyi")


def test_stub_examples_run():
    text = STUBS.read_text()
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    tree = ast.parse(text)
    examples = 0
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.ClassDef, ast.Module)):
            doc = ast.get_docstring(node, clean=True)
            if doc and ">>>" in doc:
                name = getattr(node, "name", "module")
                test = parser.get_doctest(doc, {"surftopo": surftopo, "np": np}, name, str(STUBS), 0)
                examples += len(test.examples)
                runner.run(test)
    assert examples >= 20
    assert runner.failures == 0, f"{runner.failures} stub examples failed (see the output above)"


def test_package_docstring_example_runs():
    failures, tried = doctest.testmod(surftopo, extraglobs={"surftopo": surftopo})
    assert tried > 0 and failures == 0


def test_stubs_cover_the_public_api():
    tree = ast.parse(STUBS.read_text())
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {a.asname for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names
                if a.asname}
    assert stubbed == set(surftopo.__all__)
    declared = next(n.value for n in tree.body if isinstance(n, ast.Assign)
                    and any(getattr(t, "id", None) == "__all__" for t in n.targets))
    assert sorted(ast.literal_eval(declared)) == sorted(surftopo.__all__)
    for name in surftopo.__all__:
        assert getattr(surftopo, name).__doc__, f"{name} has no docstring"
