# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.resample: a scan brought into a fit's topology, its settings the command line's, bad input named."""
import numpy as np
import pytest

import morphreg


@pytest.fixture(scope="module")
def fit(model, scan):
    return morphreg.register(model, scan.points, scan.normals, components=5)


@pytest.fixture(scope="module")
def resampled(fit, scan):
    return morphreg.resample(fit.vertices, fit.faces, scan.points, scan.normals)


def test_observed_vertices_lie_on_the_unseen_head(resampled, fit, scan, truth):
    pose = scan.head_to_scan
    true_vertices = truth.vertices @ pose[:3, :3].T + pose[:3, 3]
    errors = np.linalg.norm(resampled.vertices - true_vertices, axis=1)
    observed = resampled.observed
    report = resampled.report
    assert report["coverage"] == pytest.approx(observed.mean())
    assert observed.mean() > 0.7  # the simulated laser scan leaves the crown and under the chin unseen
    # on the scan: within its noise of the truth (mm), and closer than the fit itself (the reference returned
    # unchanged would not pass)
    fit_errors = np.linalg.norm(fit.vertices - true_vertices, axis=1)
    assert np.median(errors[observed]) < 0.5
    assert np.median(errors[observed]) < 0.95 * np.median(fit_errors[observed])  # 0.329 against 0.364 mm
    assert resampled.vertices.shape == (3458, 3) and resampled.faces.shape == (6912, 3)
    assert np.allclose(resampled.displacement, resampled.vertices - fit.vertices)


def test_settings_are_the_command_lines(fit, scan):
    one_pass = morphreg.resample(fit.vertices, fit.faces, scan.points, scan.normals, passes=1, ray_distance=2.5)
    assert one_pass.report["settings"]["passes"] == 1
    assert one_pass.report["settings"]["ray_distance_mm"] == 2.5
    assert "ray_distance = 5" in morphreg.resample.__doc__


@pytest.mark.parametrize("settings, error, message", [
    ({"passes": 0}, morphreg.InvalidInputError, "resampling setting passes = 0 is out of range"),
    ({"ray_distance": float("nan")}, morphreg.InvalidInputError, "ray_distance = nan is out of range"),
    ({"passes": 2.5}, TypeError, "passes must be an int"),
    ({"ray_distanse": 5.0}, TypeError, "unexpected keyword argument 'ray_distanse'"),
])
def test_bad_settings_are_named(fit, scan, settings, error, message):
    with pytest.raises(error, match=message):
        morphreg.resample(fit.vertices, fit.faces, scan.points, scan.normals, **settings)


def test_a_scan_elsewhere_is_refused(fit, scan):
    with pytest.raises(morphreg.InvalidInputError):
        morphreg.resample(fit.vertices, fit.faces, scan.points + 1000.0, scan.normals)
