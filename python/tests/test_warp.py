# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.ThinPlateSpline, MovingLeastSquaresWarp, SegmentedWarp and evaluate_warp; equal to the C++ API."""
import numpy as np
import pytest

import morphreg
from conftest import cpp_reference, relative_difference

RNG = np.random.default_rng(5)
SOURCE = RNG.uniform(-100, 100, size=(12, 3))
TARGET = SOURCE + RNG.normal(scale=5, size=(12, 3))


def test_spline_interpolates_its_landmarks():
    spline = morphreg.ThinPlateSpline()
    spline.fit(SOURCE, TARGET)
    assert spline.is_fitted and spline.bending_energy > 0
    assert np.max(np.abs(spline(SOURCE) - TARGET)) < 1e-9
    assert spline.weights.shape == (12, 3) and spline.affine.shape == (4, 3)
    assert np.array_equal(spline.landmarks, SOURCE) and spline.regularization == 0.0


def test_spline_of_an_affine_map_is_that_map():
    linear = np.array([[1.1, 0.1, 0.0], [0.0, 0.9, 0.2], [0.05, 0.0, 1.0]])
    spline = morphreg.ThinPlateSpline()
    spline.fit(SOURCE, SOURCE @ linear.T + [1.0, 2.0, 3.0])
    points = RNG.uniform(-150, 150, size=(50, 3))
    assert np.max(np.abs(spline.evaluate(points) - (points @ linear.T + [1.0, 2.0, 3.0]))) < 1e-8
    assert spline.bending_energy == pytest.approx(0.0, abs=1e-9)


def test_spline_equals_the_cpp_api(tmp_path):
    points = RNG.uniform(-120, 120, size=(200, 3))
    spline = morphreg.ThinPlateSpline(regularization=0.5)
    spline.fit(SOURCE, TARGET)
    reference = cpp_reference({"tps": {"source": SOURCE.tolist(), "target": TARGET.tolist(),
                                       "points": points.tolist(), "regularization": 0.5}}, tmp_path)
    assert relative_difference(spline(points), reference["tps"]) <= 1e-9
    assert relative_difference(spline(points.astype(np.float32)), spline(points.astype(np.float32).astype(float))) == 0


def test_spline_bad_input():
    spline = morphreg.ThinPlateSpline()
    with pytest.raises(morphreg.Error, match="evaluate"):
        spline(SOURCE)
    with pytest.raises(morphreg.InvalidInputError, match="source has 12 landmarks and target 11"):
        spline.fit(SOURCE, TARGET[:11])
    with pytest.raises(morphreg.InvalidInputError, match="target: row 2, column 0 is not finite"):
        spline.fit(SOURCE, np.where(np.arange(36).reshape(12, 3) == 6, np.inf, TARGET))
    with pytest.raises(morphreg.InvalidInputError):
        spline.fit(SOURCE[:3], TARGET[:3])  # three landmarks span no 3D affine map
    with pytest.raises(morphreg.InvalidInputError, match="regularization|lambda"):
        morphreg.ThinPlateSpline(regularization=-1.0)


def test_moving_least_squares_interpolates_and_keeps_affine_maps():
    warp = morphreg.MovingLeastSquaresWarp()
    warp.set_landmarks(SOURCE, TARGET)
    assert np.max(np.abs(warp(SOURCE) - TARGET)) < 1e-9
    assert warp.falloff == 1.0 and warp.merged_landmarks == 0
    linear = np.array([[1.1, 0.1, 0.0], [0.0, 0.9, 0.2], [0.05, 0.0, 1.0]])
    warp.set_landmarks(SOURCE, SOURCE @ linear.T + [1.0, 2.0, 3.0])
    points = RNG.uniform(-150, 150, size=(50, 3))
    assert np.max(np.abs(warp.evaluate(points) - (points @ linear.T + [1.0, 2.0, 3.0]))) < 1e-8


def test_moving_least_squares_equals_the_cpp_api(tmp_path):
    points = RNG.uniform(-120, 120, size=(200, 3))
    warp = morphreg.MovingLeastSquaresWarp(falloff=1.5)
    warp.set_landmarks(SOURCE, TARGET)
    reference = cpp_reference({"mls": {"source": SOURCE.tolist(), "target": TARGET.tolist(),
                                       "points": points.tolist(), "falloff": 1.5}}, tmp_path)
    assert relative_difference(warp(points), reference["mls"]) <= 1e-12


def test_moving_least_squares_bad_input():
    warp = morphreg.MovingLeastSquaresWarp()
    with pytest.raises(morphreg.InvalidInputError, match="no landmarks set"):
        warp(SOURCE)
    with pytest.raises(morphreg.InvalidInputError, match="source has 12 landmarks and target 11"):
        warp.set_landmarks(SOURCE, TARGET[:11])
    flat = SOURCE.copy()
    flat[:, 2] = 0.0
    with pytest.raises(morphreg.InvalidInputError, match="coplanar"):
        warp.set_landmarks(flat, TARGET)
    with pytest.raises(morphreg.InvalidInputError, match="falloff exponent"):
        morphreg.MovingLeastSquaresWarp(falloff=0.0)


def two_segments(generator):
    """The synthetic head cut at z = 0 into two labelled segments, and landmarks moving its top half."""
    vertices = generator.sample(3).vertices
    labels = (vertices[:, 2] > 0).astype(np.int32)
    source = vertices[list(generator.landmarks.values())]
    target = source + np.where(source[:, 2:3] > 0, [4.0, 0.0, 2.0], 0.0)
    return vertices, labels, source, target


def test_segmented_warp_equals_the_cpp_api(generator, tmp_path):
    vertices, labels, source, target = two_segments(generator)
    warp = morphreg.SegmentedWarp(labels, 2)
    warp.blend_width = 30.0
    assignment = warp.set_landmarks(vertices, generator.faces, source, target, [20.0, 20.0])
    assert len(assignment) == 2 and all(len(a) >= 4 for a in assignment)
    warped = warp.warp(vertices, generator.faces)
    reference = cpp_reference({"segmented": {
        "vertices": vertices.tolist(), "faces": generator.faces.tolist(), "labels": labels.tolist(),
        "num_segments": 2, "source": source.tolist(), "target": target.tolist(), "overlap": [20.0, 20.0],
        "blend_width": 30.0}}, tmp_path)
    assert relative_difference(warped, reference["segmented"]) <= 1e-9
    quality = morphreg.evaluate_warp(warped, warped, generator.faces, labels)
    assert quality["mean_error"] == 0.0 and quality["folded"] == 0


def test_segment_by_segment(generator):
    """Landmarks given per segment, a blend width per segment and regularised splines."""
    vertices, labels, source, target = two_segments(generator)
    top = source[:, 2] > 0
    warp = morphreg.SegmentedWarp(labels, 2)
    warp.set_regularization(0.1)
    warp.set_segment_landmarks(0, source[~top], target[~top])
    warp.set_segment_landmarks(1, source[top], target[top])
    warp.set_segment_blend_width(1, 50.0)
    warped = warp.warp(vertices, generator.faces)
    assert np.allclose(warped[labels == 0][vertices[labels == 0, 2] < -60], vertices[labels == 0][
        vertices[labels == 0, 2] < -60], atol=0.5)  # far below the seam the bottom half stays
    moved = warped[labels == 1] - vertices[labels == 1]
    assert np.allclose(np.median(moved, axis=0), [4.0, 0.0, 2.0], atol=0.5)
    assert warp.num_segments == 2


def test_segmented_warp_bad_input(generator):
    vertices, labels, source, target = two_segments(generator)
    with pytest.raises(morphreg.InvalidInputError, match="labels"):
        morphreg.SegmentedWarp(labels.astype(float), 2)
    warp = morphreg.SegmentedWarp(labels, 2)
    with pytest.raises(morphreg.InvalidInputError, match="mesh faces: face 0 has vertex index -1"):
        warp.warp(vertices, -np.ones((5, 3), dtype=np.int32))
    with pytest.raises(morphreg.InvalidInputError):
        warp.warp(vertices, generator.faces)  # no landmarks yet
