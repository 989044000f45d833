# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.fit_photos on simulated photos: accuracy, equality with `morphreg fit-photos`, bad input."""
import json

import numpy as np
import pytest

import morphreg
from conftest import relative_difference, run_cli


@pytest.fixture(scope="module")
def photos(generator, truth):
    return morphreg.PhotoSimulator().photograph(truth.vertices, generator.landmarks, generator.profile_line, 3)


def test_joint_fit_recovers_the_head(model, photos, truth):
    fit = morphreg.fit_photos(model, photos.profile, photos.frontal, components=10)
    error = np.sqrt(np.mean(np.sum((fit.vertices - truth.vertices) ** 2, axis=1)))
    mean_error = np.sqrt(np.mean(np.sum((model.mean - truth.vertices) ** 2, axis=1)))
    assert error < mean_error
    assert fit.report["final"]["landmark_rms_mm"] < 1.0  # in the image, with 1 px landmark noise
    assert fit.faces.shape == model.faces.shape and fit.image_vertices.shape == fit.vertices.shape
    assert fit.report["settings"]["approach"] == "joint"
    assert fit.scale == pytest.approx(photos.scale, rel=0.05)
    assert np.allclose(fit.rotation, photos.rotation, atol=0.05)
    assert np.linalg.norm(fit.translation - photos.translation) < 0.02  # normalised photo units
    assert len(fit.coefficients) == 70
    assert fit.report["coefficients_unit"] == "prior standard deviations"
    assert relative_difference(fit.coefficients, fit.coefficients_mm / model.standard_deviations(10)) <= 1e-12
    assert relative_difference(fit.report["coefficients_mm"], fit.coefficients_mm) <= 1e-12


def test_equals_the_command_line(model_file, photos, tmp_path):
    profile, frontal = tmp_path / "profile.json", tmp_path / "frontal.json"
    photos.profile.save(str(profile))
    photos.frontal.save(str(frontal))
    run_cli("fit-photos", "--model", model_file, "--profile", profile, "--frontal", frontal, "--approach", "tps",
            "--components", 6, "--out", tmp_path / "fit.ply", "--report", tmp_path / "fit.json", "-q")
    cli = json.loads((tmp_path / "fit.json").read_text())
    fit = morphreg.fit_photos(morphreg.Model.load(model_file), morphreg.ProfileView.load(str(profile)),
                              morphreg.FrontalView.load(str(frontal)), approach="tps", components=6)
    python = fit.report
    assert relative_difference(python["coefficients"], cli["coefficients"]) <= 1e-9
    assert python["scale"] == pytest.approx(cli["scale"], rel=1e-9)
    assert (python["status"], python["warnings"], python["settings"]) == (cli["status"], cli["warnings"],
                                                                          cli["settings"])


def test_views_from_pixels(model, photos):
    profile = morphreg.ProfileView(1000, 1200, photos.profile.silhouette, photos.profile.silhouette[0])
    assert profile.silhouette.shape[1] == 2
    frontal = morphreg.FrontalView(1000, 1200, photos.frontal.landmarks)
    assert sorted(frontal.landmarks) == sorted(photos.frontal.landmarks)


def test_bad_input(model, photos):
    with pytest.raises(morphreg.InvalidInputError,
                       match="photo fitting approach \"side\" is none of profile, joint, tps"):
        morphreg.fit_photos(model, photos.profile, photos.frontal, approach="side")
    with pytest.raises(morphreg.InvalidInputError, match="0 landmarks fix model vertices; at least 3 are needed"):
        morphreg.fit_photos(model, photos.profile)
    with pytest.raises(morphreg.InvalidInputError,
                       match=r"photo fit setting smoothness = 0 is out of range \(above 0\)"):
        morphreg.fit_photos(model, photos.profile, photos.frontal, smoothness=0.0)
    with pytest.raises(TypeError, match="fit_photos\\(\\) got an unexpected keyword argument 'lambda1'"):
        morphreg.fit_photos(model, photos.profile, photos.frontal, lambda1=0.5)
    with pytest.raises(morphreg.InvalidInputError, match=r"silhouette: shape \(10, 3\), expected \(N, 2\)"):
        morphreg.ProfileView(1000, 1200, np.zeros((10, 3)), [0.0, 0.0])
    with pytest.raises(morphreg.InvalidInputError, match="expected a dict"):
        morphreg.FrontalView(1000, 1200, [(1, 2)])
