# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures of the Python tests: a small synthetic model, an unseen head and its scan, and runners for the
command line and the C++ reference program (their answers are what the equality checks compare against)."""
import json
import os
import subprocess

import numpy as np
import pytest

import morphreg

RESOLUTION = 24  # 3458-vertex heads: quick to build and fit


def relative_difference(actual, expected):
    """The largest absolute difference over the largest magnitude of the expected values."""
    actual, expected = np.asarray(actual, dtype=float), np.asarray(expected, dtype=float)
    assert actual.shape == expected.shape
    return np.max(np.abs(actual - expected)) / max(np.max(np.abs(expected)), 1e-300)


@pytest.fixture(scope="session")
def generator():
    return morphreg.HeadGenerator(RESOLUTION)


@pytest.fixture(scope="session")
def model(generator):
    heads = generator.population(40, 1)
    return morphreg.Model.build([h.vertices for h in heads], generator.faces, regions=generator.regions,
                                components=10, landmarks=generator.landmarks, profile_line=generator.profile_line)


@pytest.fixture(scope="session")
def model_file(model, tmp_path_factory):
    path = str(tmp_path_factory.mktemp("model") / "model.h5")
    model.save(path)
    return path


@pytest.fixture(scope="session")
def truth(generator):
    return generator.sample(1001)


@pytest.fixture(scope="session")
def scan(truth):
    return morphreg.ScanSimulator(angular_samples=200, row_spacing=3.0).scan(truth.vertices, truth.faces, 7)


def run_cli(*args):
    """Runs the morphreg command line; returns its completed process (check=True)."""
    return subprocess.run([os.environ["MORPHREG_CLI"], *map(str, args)], check=True, capture_output=True, text=True)


def cpp_reference(request, tmp_path):
    """The C++ API's answers to a request (see cpp_reference.cpp)."""
    request_file, result_file = tmp_path / "request.json", tmp_path / "result.json"
    request_file.write_text(json.dumps(request))
    subprocess.run([os.environ["MORPHREG_PYTHON_REFERENCE"], str(request_file), str(result_file)], check=True)
    return json.loads(result_file.read_text())
