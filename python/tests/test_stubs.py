# SPDX-License-Identifier: BSD-3-Clause
"""The type stubs (morphreg/__init__.pyi) describe exactly the module: every public name, every class member and
every function's parameters, so editors complete what exists."""
import ast
import inspect
import os
import re

import pytest

import morphreg

STUBS = ast.parse(open(os.path.join(os.path.dirname(morphreg.__file__), "__init__.pyi")).read())
ALIASES = {"ArrayLike", "Points", "Faces", "Components"}


def stub_definitions(body):
    return {node.name: node for node in body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}


def stub_class_members(node):
    members = set(stub_definitions(node.body))
    members |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
    return members - {"__init__"}


def public_names():
    return {name for name in dir(morphreg) if not name.startswith("_")}


def parameters_of(function):
    """Parameter names from pybind11's signature line, e.g. "register(model: ..., points: ..., *, progress...)"."""
    signature = function.__doc__.splitlines()[0]
    inner = signature[signature.index("(") + 1:signature.rindex(")")]
    names = re.findall(r"(?:^|, )(\*|\w+)(?=: |, |$)", inner)
    return [name for name in names if name not in ("*", "self")]


def stub_parameters(node):
    args = node.args
    return [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs if a.arg != "self"]


def test_every_public_name_has_a_stub():
    stubbed = set(stub_definitions(STUBS.body)) | ALIASES
    assert public_names() == stubbed - ALIASES


@pytest.mark.parametrize("name", sorted(n for n, node in stub_definitions(STUBS.body).items()
                                        if isinstance(node, ast.ClassDef)))
def test_class_members_match(name):
    cls = getattr(morphreg, name)
    if issubclass(cls, BaseException):
        return
    actual = {m for m in vars(cls) if not m.startswith("_") or m == "__call__"}
    assert stub_class_members(stub_definitions(STUBS.body)[name]) == actual


KEYWORD_TABLES = {"register": "_registration_options", "register_study": "_registration_options",
                  "resample": "_resampling_options", "fit_photos": "_photo_fit_options"}


def keyword_settings(function):
    """The settings a function takes as **keywords: the table the command line reads too (registration_options.h,
    resampling_settings.h, photo_fit_options.h), as name -> (default as Python writes it, help)."""
    return getattr(morphreg, KEYWORD_TABLES.get(function.__name__, ""), {})


@pytest.mark.parametrize("name", sorted(n for n, node in stub_definitions(STUBS.body).items()
                                        if isinstance(node, ast.FunctionDef)))
def test_function_parameters_match(name):
    function = getattr(morphreg, name)
    expected = parameters_of(function) + list(keyword_settings(function))
    assert stub_parameters(stub_definitions(STUBS.body)[name]) == expected


@pytest.mark.parametrize("name", sorted(KEYWORD_TABLES))
def test_keyword_defaults_are_the_tables(name):
    node = stub_definitions(STUBS.body)[name]
    stub_defaults = {arg.arg: ast.literal_eval(ast.unparse(default))
                     for arg, default in zip(node.args.kwonlyargs, node.args.kw_defaults)}
    table = keyword_settings(getattr(morphreg, name))
    assert table
    for setting, (default, _) in table.items():
        assert stub_defaults[setting] == ast.literal_eval(default), setting


def test_functions_have_docstrings():
    for name in public_names():
        item = getattr(morphreg, name)
        if inspect.isbuiltin(item) or inspect.isclass(item):
            assert item.__doc__ and len(item.__doc__.strip()) > 20, name
