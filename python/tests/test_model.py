# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.Model: files, mean, regions, components, instances, samples and projections; equal to the C++ API."""
import json

import numpy as np
import pytest

import morphreg
from conftest import cpp_reference, relative_difference, run_cli


def test_load_gives_the_saved_model(model, model_file):
    loaded = morphreg.Model.load(model_file)
    assert loaded.num_vertices == model.num_vertices == 3458
    assert loaded.num_regions == 7 and loaded.component_counts == model.component_counts
    assert np.array_equal(loaded.mean, model.mean)
    assert np.array_equal(loaded.faces, model.faces)
    assert loaded.landmarks == model.landmarks and loaded.profile_line == model.profile_line
    assert relative_difference(loaded.components(), model.components()) <= 1e-12


def test_describe_is_model_info(model_file):
    described = morphreg.Model.load(model_file).describe()
    printed = json.loads(run_cli("model-info", "--model", model_file, "--json").stdout)
    assert printed["file"] == model_file and described["file"] == ""
    for key in ("vertices", "triangles", "regions", "global_pca", "landmarks", "units", "file_units"):
        assert described[key] == printed[key], key
    assert described["vertices"] == 3458 and len(described["regions"]) == 7


def test_mean_is_a_read_only_view(model):
    mean = model.mean
    assert mean.shape == (3458, 3) and mean.dtype == np.float64
    assert not mean.flags.writeable
    assert np.shares_memory(mean, model.mean)  # no copy: both view the model's own vector
    with pytest.raises(ValueError):
        mean[0, 0] = 1.0


def test_regions(model, generator):
    regions = model.regions
    assert [r["name"] for r in regions] == generator.regions[0]
    for region in regions:
        assert region["basis"].shape == (3 * len(region["vertices"]), len(region["variances"]))
        assert np.all(np.diff(region["variances"]) <= 0) and np.all((0 <= region["weights"]) & (region["weights"] <= 1))


def test_instance_is_mean_plus_components(model):
    selection = [3] * 7
    coefficients_mm = np.random.default_rng(2).normal(size=21)
    shape_matrix = model.components(selection)
    assert shape_matrix.shape == (3 * 3458, 21)
    expected = model.mean + (shape_matrix @ coefficients_mm).reshape(-1, 3)
    assert relative_difference(model.instance_mm(coefficients_mm, selection), expected) <= 1e-12
    assert np.array_equal(model.instance(np.zeros(21), 3), model.mean)
    assert model.variances(3).shape == (21,)


def test_coefficients_are_in_prior_standard_deviations(model):
    """statismo's convention: instance(c) = mean + components @ (c * sqrt(variances))."""
    sd = model.standard_deviations(4)
    assert np.allclose(sd, np.sqrt(model.variances(4)), rtol=1e-12)
    coefficients = np.random.default_rng(5).normal(size=28)
    expected = model.mean + (model.components(4) @ (coefficients * sd)).reshape(-1, 3)
    assert relative_difference(model.instance(coefficients, 4), expected) <= 1e-12
    assert relative_difference(model.instance(coefficients, 4), model.instance_mm(coefficients * sd, 4)) <= 1e-12


def test_project_recovers_coefficients(model):
    coefficients = np.random.default_rng(3).normal(size=35)
    recovered = model.project(model.instance(coefficients, 5), 5)
    assert np.max(np.abs(recovered - coefficients)) < 1e-6
    in_mm = model.project_mm(model.instance(coefficients, 5), 5)
    assert np.max(np.abs(in_mm - coefficients * model.standard_deviations(5))) < 1e-6


def test_sample_is_seeded(model):
    assert np.array_equal(model.sample(4, 5), model.sample(4, 5))
    assert not np.array_equal(model.sample(4, 5), model.sample(5, 5))


def test_equals_the_cpp_api(model_file, tmp_path):
    model = morphreg.Model.load(model_file)
    coefficients = list(np.linspace(-20, 20, 35))
    reference = cpp_reference({"model": {"path": model_file, "coefficients": coefficients, "components": 5,
                                         "seed": 11}}, tmp_path)["model"]
    assert relative_difference(model.instance_mm(coefficients, 5), reference["instance"]) <= 1e-9
    assert relative_difference(model.sample(11, 5), reference["sample"]) <= 1e-9


def test_bad_arguments_are_named(model, tmp_path):
    with pytest.raises(morphreg.InvalidInputError, match="coefficients .*: 3 values, expected 70"):
        model.instance(np.zeros(3))
    with pytest.raises(morphreg.InvalidInputError, match="components"):
        model.instance(np.zeros(3), "all")
    with pytest.raises(morphreg.InvalidInputError, match="vertices: shape"):
        model.project(np.zeros((10, 3, 1)))
    with pytest.raises(morphreg.IoError, match="missing.h5"):
        morphreg.Model.load(str(tmp_path / "missing.h5"))
    corrupt = tmp_path / "corrupt.h5"
    corrupt.write_bytes(b"\x89HDF\r\n\x1a\n" + b"\0" * 100)
    with pytest.raises(morphreg.FormatError, match="corrupt.h5"):
        morphreg.Model.load(str(corrupt))
    with pytest.raises(morphreg.InvalidInputError, match="meshes\\[1\\]"):
        morphreg.Model.build([model.mean, model.mean[:-1]], model.faces)
    with pytest.raises(morphreg.InvalidInputError, match=r"model builder setting variance = 0 is out of range"):
        morphreg.Model.build([model.mean, model.mean], model.faces, variance=0.0)
    with pytest.raises(TypeError, match=r"Model.build\(\) got an unexpected keyword argument 'align'"):
        morphreg.Model.build([model.mean, model.mean], model.faces, align=False)


def test_build_equals_the_command_line(generator, tmp_path):
    """Model.build on meshes read back from files against `morphreg build-model --mesh ...` on the same files."""
    files = []
    for i, head in enumerate(generator.population(12, 50)):
        files.append(str(tmp_path / f"head_{i}.ply"))
        morphreg.save_mesh(files[-1], head.vertices, head.faces)
    meshes = [morphreg.load_mesh(f)[0] for f in files]
    python = morphreg.Model.build(meshes, generator.faces, components=6)
    arguments = [a for f in files for a in ("--mesh", f)]
    run_cli("build-model", *arguments, "--components", 6, "--out", tmp_path / "cli.h5", "-q")
    cli = morphreg.Model.load(str(tmp_path / "cli.h5"))
    assert relative_difference(python.mean, cli.mean) <= 1e-9
    assert relative_difference(python.variances(), cli.variances()) <= 1e-9
    # Components are defined up to their sign.
    a, b = python.components(), cli.components()
    signs = np.sign(np.sum(a * b, axis=0))
    assert relative_difference(a * signs, b) <= 1e-9
