# The benchmark run in-process from Python (headless OpenGL), and its results read back.
import json

import numpy as np
import pytest


def tiny(fv, **kw):
    args = dict(scene="cheap", techniques=["native", "layered"], size=(64, 36), frames=2, warmup=1)
    args.update(kw)
    return fv.bench(**args)


def test_a_tiny_bench_returns_native_and_a_technique(fv, tmp_path):
    r = tiny(fv, out=str(tmp_path), images=True)
    assert r["schema"] == "foveate-bench/1"
    assert r["scene"] == "cheap" and r["size"] == [64, 36] and r["frames"] == 2
    names = [x["technique"] for x in r["results"]]
    assert names == ["native", "layered"]
    native, layered = r["results"]
    assert native["speedup"] == 1.0
    assert native["quality"] == {}  # native is the reference
    assert len(layered["frame_ms"]) == 2 and all(ms > 0 for ms in layered["frame_ms"])
    lo, hi = layered["speedup_ci95"]
    assert lo <= layered["speedup"] <= hi
    assert layered["speedup"] == pytest.approx(native["mean_ms"] / layered["mean_ms"])
    assert layered["pixel_ratio"] == pytest.approx(layered["shaded_pixels"] / layered["native_pixels"])
    assert layered["native_pixels"] == 64 * 36
    assert layered["parameters"]["layers"] == 2  # layered's own
    assert 0.5 < layered["quality"]["ssim"] <= 1.0 and layered["quality"]["frames"] == 2
    # The frames, and the metrics on them agree with the module's own.
    assert r["native_image"].shape == (36, 64, 3) and r["native_image"].dtype == np.uint8
    np.testing.assert_array_equal(native["image"], r["native_image"])
    assert layered["image"].shape == (36, 64, 3)
    assert fv.ssim(r["native_image"], r["native_image"]) == pytest.approx(1.0)
    # The files of `foveate bench --out`, read back.
    back = fv.read_results(str(tmp_path))
    assert [x["technique"] for x in back["results"]] == names
    assert back["results"][1]["median_ms"] == pytest.approx(layered["median_ms"])
    with open(tmp_path / "results.json") as f:
        assert json.load(f)["command"] == "foveate.bench (Python)"
    # Timed pass by pass where the renderer has no GPU timers (llvmpipe).
    assert isinstance(r["environment"]["pass_by_pass"], bool)
    if "llvmpipe" in r["environment"]["renderer"]:
        assert r["environment"]["pass_by_pass"]
    # Judged: timed in a pass that read nothing back, then rendered again.
    assert r["environment"]["timed_apart"] is True
    assert (tmp_path / "report.html").stat().st_size > 0


def test_parameters_sweeps_and_video(fv, tmp_path):
    r = tiny(fv, techniques=["layered"], params={"layered.layers": 3}, metrics=False)
    assert r["environment"]["timed_apart"] is False  # nothing judged: one pass
    # native first, listed or not: the reference of every speedup and JOD below native
    assert [x["technique"] for x in r["results"]] == ["native", "layered"]
    assert r["results"][1]["parameters"]["layers"] == 3
    s = tiny(fv, techniques=["layered"], sweep=("slope", 0.02, 0.03, 0.01), metrics=False, frames=1)
    assert [x["sweep_value"] for x in s["results"][1:]] == pytest.approx([0.02, 0.03])
    listed = tiny(fv, techniques=["layered"], sweep=("margin", [2, 1]), metrics=False, frames=1)
    assert [x["sweep_value"] for x in listed["results"][1:]] == [1.0, 2.0]
    m = tiny(fv, techniques=["checkerboard"], size=(640, 360), margin=2.0, metrics=False, frames=1)
    plain = tiny(fv, techniques=["checkerboard"], size=(640, 360), metrics=False, frames=1)
    assert m["margin"] == 2.0 and plain["margin"] is None  # None: each technique's own
    assert m["results"][1]["parameters"]["margin"] == 2.0
    assert plain["results"][1]["parameters"]["margin"] == 1.0
    assert m["results"][1]["parameters"]["r1"] > plain["results"][1]["parameters"]["r1"]
    video = tmp_path / "b.mp4"
    v = tiny(fv, techniques=["layered"], metrics=False, video=str(video), side_by_side=True)
    assert video.stat().st_size > 0 and "2 frame(s), 128x36" in v["video"]


def test_bad_bench_input_raises(fv, tmp_path):
    with pytest.raises(fv.Error, match="techniques: unknown technique 'warp'"):
        tiny(fv, techniques=["warp"])
    with pytest.raises(fv.Error, match="size"):
        tiny(fv, size=(0, 36))
    with pytest.raises(fv.Error, match="margin: expected a factor from 1 to 4"):
        tiny(fv, margin=0.5)
    with pytest.raises(fv.Error, match="acuity_preset and slope: give one"):
        tiny(fv, acuity_preset="B", slope=0.02)
    with pytest.raises(fv.Error, match="acuity_preset and quality are one option"):
        tiny(fv, acuity_preset="B", quality="B")
    with pytest.raises(fv.Error, match="acuity_preset: expected A or B .*, got 'C'"):
        tiny(fv, quality="C")
    with pytest.raises(fv.Error, match="not a built-in scene"):
        tiny(fv, scene="nosuch")
    with pytest.raises(fv.Error, match="no such parameter|belongs to none"):
        tiny(fv, params={"nope": 1})
    with pytest.raises(TypeError, match="params\\['layers'\\]: expected a number"):
        tiny(fv, params={"layers": "three"})
    with pytest.raises(fv.Error, match="frames: expected 1..100000"):
        tiny(fv, frames=0)
    with pytest.raises(fv.Error, match="sweep slope: .* over the limit of 50"):
        tiny(fv, sweep=("slope", 0, 1, 1e-9))
    with pytest.raises(fv.Error, match="sweep margin and margin: the sweep sets each run's margin"):
        tiny(fv, margin=1.5, sweep=("margin", [1, 2]))
    with pytest.raises(fv.Error, match="sweep margin: 1 is listed twice"):
        tiny(fv, sweep=("margin", [1, 1]))
    with pytest.raises(fv.Error, match="side_by_side: only with video"):
        tiny(fv, side_by_side=True)
    with pytest.raises(fv.Error, match="vergence: only with stereo"):
        tiny(fv, vergence=2)
    with pytest.raises(fv.Error, match="frame_timeout_s: expected 0"):
        tiny(fv, frame_timeout_s=-1)
    with pytest.raises(fv.Error, match="results.json"):
        fv.read_results(str(tmp_path))
    (tmp_path / "results.json").write_text("{broken")
    with pytest.raises(fv.Error, match="not valid JSON"):
        fv.read_results(str(tmp_path / "results.json"))


def test_the_default_run_measures_every_technique_the_scene_can_run(fv):
    r = fv.bench(scene="cheap", size=(48, 27), frames=1, warmup=0, metrics=False)
    names = [x["technique"] for x in r["results"]]
    listed = [t["name"] for t in fv.techniques()]
    assert names == [n for n in listed if n != "lodmask"]  # lodmask needs meshes
    assert r["skipped"][0].startswith("lodmask (")


def test_a_stereo_bench_reports_each_eye(fv):
    r = tiny(fv, scene="guenter", display="hmd-quest2", size=(48, 48), stereo=True, vergence="2",
             images=True)
    s = r["stereo"]
    assert s["eye_size"] == [48, 48] and s["output_size"] == [96, 48] and s["vergence_m"] == 2
    layered = r["results"][1]
    assert layered["image"].shape == (48, 96, 3)  # the two eyes side by side
    left, right = layered["eyes"]["left"], layered["eyes"]["right"]
    assert left["shaded_pixels"] + right["shaded_pixels"] == pytest.approx(layered["shaded_pixels"])
    assert left["quality"]["frames"] == 2 and layered["quality"]["frames"] == 4
    with pytest.raises(fv.Error, match="not a stereo head-mounted display"):
        tiny(fv, display="hmd-quest3", stereo=True)


def test_tune_chooses_within_the_bound_and_writes_its_files(fv, tmp_path):
    t = fv.tune(scenes=["cheap"], techniques=["inset"], size=(96, 54), frames=2, warmup=1,
                reference="ssaa:2", bound=0.5, out=str(tmp_path))
    assert set(t["native_jod"]) == {"cheap"}
    points = [p for p in t["points"] if p["technique"] == "inset"]
    margins = [p for p in points if set(p["params"]) == {"margin"}]
    assert len(margins) == 6  # every tuned margin, the rest at their defaults
    for p in points:
        assert p["within_bound"] == (p["below_native"] <= 0.5)
        lo, hi = p["speedup_ci95"]
        assert 0 < lo <= p["speedup"] <= hi
    # On the cheap scene every margin is within the bound; the choice is one of them.
    within = [p for p in points if p["within_bound"]]
    assert within and any(p["params"] == t["chosen"]["inset"] for p in within)
    assert t["warmup_frames"] >= 1
    params = json.loads((tmp_path / "params.json").read_text())
    assert params["techniques"]["inset"] == t["chosen"]["inset"]
    assert (tmp_path / "tune.md").read_text().startswith("Within 0.50 JOD of native")
    with pytest.raises(fv.Error, match="holds the output of an earlier run"):
        fv.tune(scenes=["cheap"], techniques=["inset"], size=(96, 54), out=str(tmp_path))
    with pytest.raises(fv.Error, match="techniques: native is the baseline"):
        fv.tune(scenes=["cheap"], techniques=["native"])
    with pytest.raises(fv.Error, match="bound_jod: expected a JOD distance"):
        fv.tune(scenes=["cheap"], bound=0)
    with pytest.raises(fv.Error, match="scenes: give at least one scene"):
        fv.tune(scenes=[])
    with pytest.raises(fv.Error, match="values vrs.adapt: none of techniques has that parameter"):
        fv.tune(scenes=["cheap"], techniques=["inset"], values={"vrs.adapt": [0.3]})
    v = fv.tune(scenes=["cheap"], techniques=["inset"], size=(96, 54), frames=2, warmup=1,
                reference="ssaa:2", bound=0.5, values={"margin": [2, 1], "inset.scale": [0.45]})
    assert {p["params"]["margin"] for p in v["points"]} == {1, 2}
    assert v["settings"]["values"] == {"inset.scale": [0.45], "margin": [1, 2]}


def test_shards_merged_equal_one_run(fv, tmp_path):
    small = dict(scene="cheap", techniques=["native", "layered", "inset", "checkerboard"],
                 size=(96, 54), frames=2, warmup=1, metrics=False)
    whole = fv.bench(**small)
    for k in (1, 2):
        fv.bench(**small, shard=f"{k}/2", out=str(tmp_path / f"s{k}"))
    merged = fv.merge([str(tmp_path / "s1"), str(tmp_path / "s2" / "results.json")],
                      out=str(tmp_path / "m"))
    assert merged["shard"] == {"merged": 2}
    assert (tmp_path / "m" / "report.html").exists()
    runs = lambda r: [(t["technique"], t["shaded_pixels"]) for t in r["results"]]
    assert runs(merged) == runs(whole)
    with pytest.raises(fv.Error, match="shard 2 of 2 is not given"):
        fv.merge([str(tmp_path / "s1")])
    with pytest.raises(fv.Error, match="shard: expected K/N"):
        fv.bench(**small, shard="3/2")
    with pytest.raises(fv.Error, match="shard: expected K/N"):
        fv.tune(scenes=["cheap"], shard="x")


def test_runs_beyond_the_memory_limit_are_judged_in_groups(fv):
    small = dict(scene="cheap", techniques=["native", "layered", "inset", "checkerboard"],
                 size=(96, 54), frames=2, warmup=1, reference="ssaa:2")
    whole = fv.bench(**small)
    # One run at 96x54 over 2 frames holds about 1.1 MB: native and one at a time.
    grouped = fv.bench(**small, memory_limit=2.5e6)
    assert whole["memory_groups"] == 1 and grouped["memory_groups"] == 3
    runs = lambda r: [(t["technique"], t["shaded_pixels"], t["quality"]["jod"])
                      for t in r["results"]]
    assert runs(grouped) == runs(whole)
    with pytest.raises(fv.Error, match="memory_limit: .* holds not even native and one run"):
        fv.bench(**small, memory_limit=1e6)


def test_tune_shards_merge(fv, tmp_path):
    small = dict(scenes=["cheap"], techniques=["inset"], size=(96, 54), frames=2, warmup=1,
                 reference="ssaa:2", bound=0.5)
    for k in (1, 2):
        fv.tune(**small, shard=f"{k}/2", out=str(tmp_path / f"t{k}"))
    merged = fv.merge([str(tmp_path / "t1"), str(tmp_path / "t2")])
    assert merged["shard"] == {"merged": 2}
    assert "inset" in merged["chosen"]
    fv.bench(scene="cheap", techniques=["inset"], size=(96, 54), frames=2, warmup=1,
             metrics=False, out=str(tmp_path / "b"))
    with pytest.raises(fv.Error, match="a benchmark's results, but .* is a tune run's"):
        fv.merge([str(tmp_path / "t1"), str(tmp_path / "b")])


def test_a_supersampled_reference_without_the_metrics_is_refused_naming_the_keywords(fv):
    with pytest.raises(fv.Error, match="reference: the supersampled reference is what the image "
                       "metrics judge against, and metrics turns them off"):
        fv.bench(scene="cheap", techniques=["layered"], size=(48, 27), frames=1, warmup=0,
                 metrics=False, reference="ssaa:2")
