# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.HeadGenerator and ScanSimulator: deterministic, equal to the C++ API, bad settings named."""
import numpy as np
import pytest

import morphreg
from conftest import RESOLUTION, cpp_reference, relative_difference


def test_heads_are_deterministic_and_equal_the_cpp_api(generator, tmp_path):
    head = generator.sample(5)
    assert np.array_equal(head.vertices, generator.sample(5).vertices)
    assert len(head.parameters) == 20 == len(generator.parameter_names)
    reference = cpp_reference({"head": {"resolution": RESOLUTION, "seed": 5}}, tmp_path)
    assert relative_difference(head.vertices, reference["head"]) <= 1e-9


def test_generate_from_parameters(generator):
    mean_head = generator.generate({})
    long_nose = generator.generate({"nose_length": 60.0})
    assert long_nose.parameters["nose_length"] == 60.0
    assert not np.allclose(mean_head.vertices, long_nose.vertices)
    with pytest.raises(morphreg.InvalidInputError, match="no head parameter \"nose_size\""):
        generator.generate({"nose_size": 60.0})
    with pytest.raises(morphreg.InvalidInputError, match="nose_length"):
        generator.generate({"nose_length": -5.0})
    names, labels = generator.regions
    assert len(names) == 7 and len(labels) == generator.num_vertices and labels == generator.region_labels
    assert set(generator.landmarks) >= {"nose_tip", "chin"} and len(generator.profile_line) > 20


def test_scans_equal_the_cpp_api(generator, tmp_path):
    head = generator.sample(8)
    scan = morphreg.ScanSimulator(angular_samples=120, row_spacing=4.0).scan(head.vertices, head.faces, 9)
    reference = cpp_reference({"scan": {"resolution": RESOLUTION, "head_seed": 8, "seed": 9, "angular_samples": 120,
                                        "row_spacing": 4.0}}, tmp_path)["scan"]
    assert relative_difference(scan.points, reference["points"]) <= 1e-9
    assert relative_difference(scan.normals, reference["normals"]) <= 1e-9
    assert scan.head_to_scan.shape == (4, 4) and scan.faces is None
    assert len(scan.source_triangle) == len(scan.points) and scan.barycentric.shape == scan.points.shape


def test_range_mesh_and_settings(truth):
    scanner = morphreg.ScanSimulator(angular_samples=100, row_spacing=5.0, range_mesh=True, outliers=0.0, noise=0.1)
    assert scanner.settings["angular_samples"] == 100 and scanner.settings["range_mesh"] is True
    assert scanner.settings["outliers"] == 0.0 and scanner.settings["noise"] == 0.1
    scan = scanner.scan(truth.vertices, truth.faces, 1)
    assert scan.faces.shape[1] == 3 and scan.faces.max() < len(scan.points) and scan.num_outliers == 0


def test_bad_scanner_settings():
    with pytest.raises(TypeError, match="ScanSimulator\\(\\) got an unexpected keyword argument 'samples'"):
        morphreg.ScanSimulator(samples=10)
    with pytest.raises(morphreg.InvalidInputError, match=r"scanner setting angular_samples = 2 is out of range"):
        morphreg.ScanSimulator(angular_samples=2)
    with pytest.raises(TypeError, match="noise must be a number"):
        morphreg.ScanSimulator(noise="loud")
    assert morphreg.ScanSimulator(scale_deviation=0.0).settings["scale_deviation"] == 0.0
