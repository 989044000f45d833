# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.register: accuracy against the truth, equality with `morphreg register`, the GIL, progress, bad input."""
import json
import sys
import threading

import numpy as np
import pytest

import morphreg
from conftest import relative_difference, run_cli


def scan_frame(scan, vertices):
    """Head vertices carried into the scan's frame by the simulator's true similarity."""
    pose = scan.head_to_scan
    return vertices @ pose[:3, :3].T + pose[:3, 3]


@pytest.fixture(scope="module")
def fit(model, scan):
    return morphreg.register(model, scan.points, scan.normals, components=5)


def test_fit_recovers_the_unseen_head(fit, scan, truth):
    errors = np.linalg.norm(fit.vertices - scan_frame(scan, truth.vertices), axis=1)
    assert fit.status == "ok"
    assert np.sqrt(np.mean(errors ** 2)) < 1.5  # mm; the model mean is off by several mm
    assert fit.scale == pytest.approx(scan.scale, rel=0.02)
    assert fit.vertices.shape == (3458, 3) and fit.faces.shape == (6912, 3)
    assert fit.residuals.shape == (3458,)


def test_refinement_prior_fits_all_components_closer(fit, model, scan, truth):
    refined = morphreg.register(model, scan.points, scan.normals, components=10, refinement_prior=0.2)
    assert refined.report["settings"]["refinement_prior_weight"] == 0.2
    assert fit.report["settings"]["refinement_prior_weight"] is None
    def rms(result):
        return np.sqrt(np.mean(np.linalg.norm(result.vertices - scan_frame(scan, truth.vertices), axis=1) ** 2))
    assert rms(refined) < 0.9 * rms(fit)


def test_result_parts_agree(fit, model):
    similarity = fit.similarity
    assert np.allclose(similarity[:3, :3], fit.scale * fit.rotation)
    assert np.allclose(similarity[:3, 3], fit.translation)
    assert np.allclose(fit.rotation @ fit.rotation.T, np.eye(3))
    report = fit.report
    assert report["status"] == fit.status and report["units"] == "mm"
    assert report["settings"]["components"] == [5]
    stacked = np.concatenate([report["coefficients"][region["name"]] for region in model.regions])
    assert np.array_equal(stacked, fit.coefficients)
    stacked_mm = np.concatenate([report["coefficients_mm"][region["name"]] for region in model.regions])
    assert np.array_equal(stacked_mm, fit.coefficients_mm)


def test_coefficients_are_lengths_over_prior_standard_deviations(fit, model):
    assert fit.report["coefficients_unit"] == "prior standard deviations"
    sd = model.standard_deviations(5)
    assert np.abs(fit.coefficients_mm).max() > 1.0  # a real fit, not the mean
    assert relative_difference(fit.coefficients, fit.coefficients_mm / sd) <= 1e-12
    vertices = model.instance(fit.coefficients, 5) @ fit.rotation.T * fit.scale + fit.translation
    # The similarity is PCL's single-precision final transformation: about 1e-5 mm at 200 mm from the origin.
    assert np.abs(vertices - fit.vertices).max() < 1e-4


def test_equals_the_command_line(model, model_file, scan, tmp_path):
    scan_file = tmp_path / "scan.pcd"
    morphreg.save_cloud(str(scan_file), scan.points, scan.normals)
    points, normals = morphreg.load_cloud(str(scan_file))
    run_cli("register", "--scan", scan_file, "--model", model_file, "--components", 5, "--out", tmp_path / "fit.ply",
            "--report", tmp_path / "fit.json", "-q")
    cli = json.loads((tmp_path / "fit.json").read_text())
    python = morphreg.register(morphreg.Model.load(model_file), points, normals, components=5)
    for region in model.regions:
        name = region["name"]
        assert relative_difference(python.report["coefficients"][name], cli["coefficients"][name]) <= 1e-9
    cli_similarity = np.array(cli["similarity"]["matrix_row_major"]).reshape(4, 4)
    assert relative_difference(python.similarity, cli_similarity) <= 1e-9
    assert python.report["residuals_mm"]["scan_to_model"] == pytest.approx(cli["residuals_mm"]["scan_to_model"],
                                                                            rel=1e-9)


def test_float32_points_give_the_float64_result(model, scan, fit):
    single = morphreg.register(model, scan.points.astype(np.float32), scan.normals.astype(np.float32), components=5)
    assert relative_difference(single.vertices, fit.vertices) <= 1e-9


def test_points_in_metres_are_converted(model, scan, fit):
    in_metres = morphreg.register(model, scan.points / 1000.0, scan.normals, components=5)
    assert in_metres.report["scan"]["units"] == "m"
    assert np.sqrt(np.mean(np.sum((in_metres.vertices - fit.vertices) ** 2, axis=1))) < 0.05  # mm


def test_progress_is_called_every_iteration(model, scan):
    calls = []
    result = morphreg.register(model, scan.points, scan.normals, components=5,
                               progress=lambda i, kept, rms: calls.append((i, kept, rms)))
    assert [c[0] for c in calls] == list(range(1, len(calls) + 1))
    assert len(calls) == result.report["iterations"]["total"]
    assert all(kept > 1000 and 0 < rms < 20 for _, kept, rms in calls)


def test_an_exception_in_progress_stops_the_fit(model, scan):
    def fail(iteration, kept, rms):
        if iteration == 3:
            raise KeyError("stop here")

    with pytest.raises(KeyError, match="stop here"):
        morphreg.register(model, scan.points, scan.normals, progress=fail)


def test_the_gil_is_released_while_fitting(model, scan):
    """The main thread runs while the fit computes only if the fit releases the GIL. The switch interval is raised so
    that Python never hands the GIL over on its own: the main thread, woken after the first iteration, can then set
    its event before the sixth iteration only through the fit's release. No timing is involved."""
    started, main_ran, seen = threading.Event(), threading.Event(), []

    def progress(iteration, kept, rms):
        if iteration == 1:
            started.set()
        if iteration == 6:
            seen.append(main_ran.is_set())

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        fit = threading.Thread(target=morphreg.register, args=(model, scan.points, scan.normals),
                               kwargs={"progress": progress, "components": 5})
        fit.start()
        assert started.wait(timeout=120), "the fit never reached its first iteration"
        main_ran.set()
        fit.join(timeout=300)
        assert not fit.is_alive(), "the fit did not end within 300 s"
    finally:
        sys.setswitchinterval(interval)
    assert seen == [True], "the main thread could not run during the fit: the GIL is held while fitting"


def test_landmarks_in_the_scan_frame(model, scan, truth, generator):
    landmarks = {name: scan_frame(scan, truth.vertices[[vertex]])[0] for name, vertex in generator.landmarks.items()}
    result = morphreg.register(model, scan.points, scan.normals, landmarks, components=5)
    assert result.status == "ok"
    nose = generator.landmarks["nose_tip"]
    assert np.linalg.norm(result.vertices[nose] - landmarks["nose_tip"]) < 3.0


@pytest.mark.parametrize("points, message", [
    (np.zeros((100, 2)), r"points: shape \(100, 2\), expected \(N, 3\)"),
    (np.zeros((100, 3), dtype=np.int64), "points: dtype int64, expected float64 or float32"),
    (np.zeros(300), r"points: shape \(300,\), expected \(N, 3\)"),
    (np.zeros((0, 3)), "points: 0 points, at least 1 needed"),
    ("scan.ply", "points: str is not an array|points: dtype <U8"),
])
def test_bad_points(model, points, message):
    with pytest.raises(morphreg.InvalidInputError, match=message):
        morphreg.register(model, points)


def test_nan_points_are_named(model, scan):
    points = scan.points.copy()
    points[17, 1] = np.nan
    with pytest.raises(morphreg.InvalidInputError, match="points: row 17, column 1 is not finite"):
        morphreg.register(model, points)


def test_degenerate_points_are_named(model):
    flat = np.random.default_rng(1).normal(size=(500, 3)) * [100, 100, 0]
    with pytest.raises(morphreg.InvalidInputError, match="points"):
        morphreg.register(model, flat)


def test_mismatched_normals(model, scan):
    with pytest.raises(morphreg.InvalidInputError, match="normals for"):
        morphreg.register(model, scan.points, scan.normals[:-1])


@pytest.mark.parametrize("settings, message", [
    ({"loss": "bisquare"}, "loss = \"bisquare\" is none of none, huber, tukey, cauchy, geman_mcclure"),
    ({"iterations": 0}, "iterations = 0 is out of range"),
    ({"tangential_weight": 2.0}, "tangential_weight = 2 is out of range"),
    ({"shape_prior": float("nan")}, "shape_prior = nan is out of range"),
    ({"refinement_prior": -1.0}, "refinement_prior = -1 is out of range"),
    ({"refinement_smoothness": -1.0}, "refinement_smoothness = -1 is out of range"),
    ({"units": "furlong"}, "furlong"),
    ({"components": "ten"}, "components: expected an int"),
    ({"components": [5, 5]}, "components has 2 counts for a model with 7 regions"),
])
def test_bad_settings(model, scan, settings, message):
    with pytest.raises(morphreg.InvalidInputError, match=message):
        morphreg.register(model, scan.points, scan.normals, **settings)


def test_unknown_setting_is_a_type_error(model, scan):
    with pytest.raises(TypeError):
        morphreg.register(model, scan.points, max_distanse=5.0)


@pytest.mark.parametrize("landmarks, message", [
    ([1, 2, 3], "landmarks: expected a dict"),
    ({"nose_tip": [1.0, 2.0]}, r"landmarks\[\"nose_tip\"\]: 2 values, expected 3"),
    ({"nosetip": [1.0, 2.0, 3.0]}, "nosetip"),
    ({"nose_tip": [1e6, 0.0, 0.0]}, "landmarks"),
])
def test_bad_landmarks(model, scan, landmarks, message):
    with pytest.raises(morphreg.InvalidInputError, match=message):
        morphreg.register(model, scan.points, scan.normals, landmarks)


def test_a_lost_scan_raises_too_few_correspondences(model, scan):
    with pytest.raises(morphreg.TooFewCorrespondencesError, match="check the max correspondence distance"):
        morphreg.register(model, scan.points, scan.normals, max_distance=0.01)  # no scan point that close
