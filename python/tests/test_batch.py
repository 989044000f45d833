# SPDX-License-Identifier: BSD-3-Clause
"""morphreg.register_study: a study registered into a folder as `morphreg register --scans` does it, resumed by a
rerun, a bad scan failing alone, bad settings named."""
import _thread
import json
import threading

import pytest

import morphreg


@pytest.fixture(scope="module")
def study(scan, tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    morphreg.save_cloud(str(folder / "head.pcd"), scan.points, scan.normals)
    (folder / "manifest.csv").write_text("scan,landmarks,id\nhead.pcd\nno_such_scan.pcd,,missing\n")
    return folder


def test_a_study_is_registered_summarised_and_resumed(model_file, study, tmp_path):
    out = tmp_path / "fits"
    result = morphreg.register_study(model_file, str(study / "manifest.csv"), str(out), components=5)
    assert result["counts"] == {"ok": 1, "failed": 1, "pending": 0}
    rows = {row["id"]: row for row in result["scans"]}
    assert rows["head"]["status"] == "ok" and rows["head"]["rms_mm"] < 2.0
    assert "no_such_scan.pcd" in rows["missing"]["reason"]
    assert json.loads((out / "summary.json").read_text())["counts"] == result["counts"]
    assert (out / "head.ply").exists() and (out / "summary.csv").exists()
    again = morphreg.register_study(model_file, str(study / "manifest.csv"), str(out), components=5)
    assert again["skipped"] == 2 and again["attempted"] == 0
    changed = morphreg.register_study(model_file, str(study / "manifest.csv"), str(out), components=5,
                                      shape_prior=6.0, retry_failed=True)
    assert changed["attempted"] == 2 and "shape_prior" in changed["redone"][0]


def test_ctrl_c_leaves_the_scans_not_started_pending(model_file, study, tmp_path):
    out = tmp_path / "fits"
    threading.Timer(0.01, _thread.interrupt_main).start()
    with pytest.raises(KeyboardInterrupt):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(out), components=5)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["counts"]["pending"] >= 1
    assert not (out / ".morphreg.lock").exists()


def test_bad_settings_are_named(model_file, study, tmp_path):
    with pytest.raises(morphreg.InvalidInputError, match="jobs 0"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "a"), jobs=0)
    with pytest.raises(morphreg.InvalidInputError, match="shard 2/2"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "b"), shard=(2, 2))
    with pytest.raises(morphreg.InvalidInputError, match="shard '2/2': expected I/N"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "b"), shard="2/2")
    with pytest.raises(TypeError, match="register_study"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "c"), no_such_setting=1)
    with pytest.raises(TypeError, match="shard must be"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "d"), shard=1.5)


def test_a_slurm_array_task_takes_its_share(model_file, study, tmp_path, monkeypatch):
    monkeypatch.delenv("SLURM_ARRAY_TASK_ID", raising=False)
    with pytest.raises(morphreg.InvalidInputError, match="SLURM_ARRAY_TASK_ID is not set"):
        morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "a"), shard="auto")
    monkeypatch.setenv("SLURM_ARRAY_TASK_ID", "11")
    monkeypatch.setenv("SLURM_ARRAY_TASK_MIN", "10")
    monkeypatch.setenv("SLURM_ARRAY_TASK_COUNT", "2")
    by_name = morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "b"), components=5,
                                      shard="1/2")
    by_slurm = morphreg.register_study(model_file, str(study / "manifest.csv"), str(tmp_path / "c"), components=5,
                                       shard="auto")
    assert [row["id"] for row in by_slurm["scans"]] == [row["id"] for row in by_name["scans"]]
    assert len(by_name["scans"]) == 1
