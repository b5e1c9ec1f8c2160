# The acuity model, displays, the planner and the other papers' models, checked
# against the papers' numbers and formulas.
import math

import numpy as np
import pytest


def test_mar_is_the_linear_model_of_guenter(fv):
    a = fv.AcuityModel.preset("A")
    assert a.slope == pytest.approx(0.0275)
    assert a.w0_deg == pytest.approx(1 / 48)
    assert a.mar_deg(10.0) == pytest.approx(0.0275 * 10 + 1 / 48)
    b = fv.AcuityModel.preset("b")
    assert b.mar_deg(20.0) == pytest.approx(0.0220 * 20 + 1 / 48)
    assert fv.SLOPE_PRESET_A == 0.0275 and fv.SLOPE_PRESET_B == 0.0220
    # The presets' former names stay.
    assert fv.AcuityModel.quality("B").slope == b.slope
    assert (fv.SLOPE_QUALITY_A, fv.SLOPE_QUALITY_B) == (fv.SLOPE_PRESET_A, fv.SLOPE_PRESET_B)
    # Vectorised over numpy arrays, and the inverse.
    e = np.array([0.0, 5.0, 30.0])
    np.testing.assert_allclose(a.mar_deg(e), 0.0275 * e + 1 / 48)
    assert a.eccentricity_for_mar(a.mar_deg(12.5)) == pytest.approx(12.5)
    assert a.eccentricity_for_mar(0.01) == 0.0  # below the foveal MAR
    assert fv.AcuityModel(slope=0.03).mar_deg(1.0) == pytest.approx(0.03 + 1 / 48)


def test_bad_acuity_input_raises(fv):
    with pytest.raises(fv.Error, match="expected A or B, got 'C'"):
        fv.AcuityModel.preset("C")
    with pytest.raises(ValueError):  # foveate.Error is a ValueError
        fv.AcuityModel.with_slope(-1.0)


def test_the_papers_display(fv):
    d = fv.Display.load("desktop-1080p")
    assert (d.width_px, d.height_px, d.width_mm, d.distance_mm) == (1920, 1080, 510, 590)
    # Guenter et al.: e* = 23.4 deg, w* = 0.0516 deg.
    assert d.half_fov_deg() == pytest.approx(23.4, abs=0.05)
    assert d.sharpness_deg() == pytest.approx(0.0516, abs=0.0001)
    assert d.eye_distance_px() == pytest.approx(1920 * 590 / 510)
    gaze = (960.0, 540.0)
    assert d.eccentricity_deg(gaze, gaze) == pytest.approx(0.0, abs=1e-9)
    expect = math.degrees(math.atan(400 / d.eye_distance_px()))
    assert d.eccentricity_deg((1360.0, 540.0), gaze) == pytest.approx(expect)
    # The same field of view at another resolution.
    small = d.resized(640, 360)
    assert small.width_px == 640 and small.half_fov_deg() == pytest.approx(d.half_fov_deg())
    assert [p.name for p in fv.Display.presets()] == [
        "desktop-1080p", "desktop-27-4k", "hmd-quest3", "hmd-quest2", "hmd-pimax-crystal",
        "hmd-rift-dk1", "hmd-quest2-lens"]
    assert d.to_dict()["width_px"] == 1920
    assert "lens" not in d.to_dict()
    # The DK1's published lens (Oculus SDK 0.2: DistortionK 1, 0.22, 0.24, 0).
    assert fv.Display.load("hmd-rift-dk1").to_dict()["lens"]["k"] == [0.22, 0.24, 0.0]


def test_asymmetric_eye(fv):
    # Edges at tangents -1 and 0.6 across 200 px: f = 125 px, the axis 125 px
    # from the left; up 0.2, down -0.6 over 100 rows: 25 px from the top.
    d = fv.Display.from_dict({"width_px": 200, "height_px": 100, "ipd_mm": 64, "fov_deg": {
        "left": -45, "right": math.degrees(math.atan(0.6)),
        "up": math.degrees(math.atan(0.2)), "down": -math.degrees(math.atan(0.6))}})
    assert d.stereo and d.ipd_mm == 64
    assert d.principal_point() == pytest.approx((125.0, 25.0))
    axis = d.principal_point()
    assert d.eccentricity_deg((0.0, 25.0), axis) == pytest.approx(45.0)
    assert d.eccentricity_deg((200.0, 25.0), axis) == pytest.approx(math.degrees(math.atan(0.6)))
    assert d.to_dict()["fov_deg"]["left"] == -45
    with pytest.raises(fv.Error, match="ipd_mm"):
        fv.Display.from_dict({"width_px": 64, "height_px": 64, "fov_h_deg": 90, "ipd_mm": 60})


def test_displays_from_dicts_and_errors(fv):
    hmd = fv.Display.from_dict({"width_px": 2064, "height_px": 2208, "fov_h_deg": 104})
    assert hmd.head_mounted
    # 104 deg across 2064 px; the longer axis (2208 px, vertical) sets e*.
    eye = 1032 / math.tan(math.radians(52))
    assert hmd.eye_distance_px() == pytest.approx(eye)
    assert hmd.half_fov_deg() == pytest.approx(math.degrees(math.atan(1104 / eye)))
    with pytest.raises(fv.Error, match="width_mm"):
        fv.Display.from_dict({"width_px": 100, "height_px": 100, "width_mm": -3, "distance_mm": 500})
    with pytest.raises(fv.Error, match="nope-display"):
        fv.Display.load("nope-display")
    with pytest.raises(TypeError, match="pixel: expected \\(x, y\\)"):
        fv.Display.load("desktop-1080p").eccentricity_deg("centre", (0, 0))


def test_planner_reproduces_the_paper(fv):
    a = fv.AcuityModel.preset("A")
    plan = fv.plan_layers("desktop-1080p", a, layers=3)
    assert len(plan.layers) == 3
    d = plan.display
    # The outer layer reaches e*, and each layer's sampling factor follows eq. 2.
    assert plan.layers[-1].radius_deg == pytest.approx(d.half_fov_deg(), abs=0.05)
    assert plan.layers[0].sampling_factor == 1.0
    for i in (1, 2):
        e = plan.layers[i - 1].radius_deg
        assert plan.layers[i].sampling_factor == pytest.approx((0.0275 * e + 1 / 48) / d.sharpness_deg())
    # The measured pixel savings: 13.3x for quality A, 9.8x for B (within 5 %).
    assert plan.pixel_ratio_half_rate() == pytest.approx(13.3, rel=0.05)
    b = fv.plan_layers(fv.Display.load("desktop-1080p"), fv.AcuityModel.preset("B"))
    assert b.pixel_ratio_half_rate() == pytest.approx(9.8, rel=0.05)
    assert plan.to_dict()["layers"][0]["sampling_factor"] == 1.0
    assert len(fv.plan_layers(layers=1).layers) == 1
    assert fv.plan_layers(layers=1).pixel_ratio() == pytest.approx(1.0)
    with pytest.raises(fv.Error, match="layers"):
        fv.plan_layers(layers=9)
    # More layers never cost more pixels.
    ratios = [fv.plan_layers(layers=n, acuity=a).pixel_ratio() for n in (2, 3, 4)]
    assert ratios[0] <= ratios[1] <= ratios[2]


def test_fov_sweep_grows_with_the_field_of_view(fv):
    rows = fv.fov_sweep(20.0, 100.0, 40.0)
    assert [r["fov_deg"] for r in rows] == [20.0, 60.0, 100.0]
    assert rows[0]["speedup_a"]["3"] < rows[1]["speedup_a"]["3"] < rows[2]["speedup_a"]["3"]
    # Quality B (a smaller slope) saves less than A.
    assert rows[2]["speedup_b"]["3"] < rows[2]["speedup_a"]["3"]


def test_swafford_latency_aware_fovea(fv):
    d = fv.Display.load("desktop-1080p")
    plain = fv.LatencyAwareFovea(fovea_deg=5.0)
    assert plain.diameter_px(d) == pytest.approx(2 * d.eye_distance_px() * math.tan(math.radians(2.5)))
    late = fv.LatencyAwareFovea(latency_ms=50.0, max_saccade_deg_per_s=200.0, fovea_deg=5.0)
    # F' = 2 d tan(L S + alpha / 2): 50 ms at 200 deg/s add 10 deg on each side.
    assert late.diameter_px(d) == pytest.approx(2 * d.eye_distance_px() * math.tan(math.radians(12.5)))
    assert late.diameter_deg(d) == pytest.approx(25.0)
    with pytest.raises(fv.Error):
        fv.LatencyAwareFovea(latency_ms=-1)


def test_meng_kernel_log_polar(fv):
    k = fv.KernelLogPolar(1920, 1080, sigma=2.0, alpha=1.0)
    assert (k.buffer_w, k.buffer_h) == (960.0, 540.0)
    assert k.log_extent() == pytest.approx(math.log(math.hypot(1920, 1080)))
    u, v = k.to_buffer((1060.0, 640.0), (960.0, 540.0))
    assert u == pytest.approx(math.log(math.hypot(100, 100)) / k.log_extent() * 960)
    assert v == pytest.approx(0.125 * 540)
    x, y = k.to_screen((u, v), (960.0, 540.0))
    assert (x, y) == (pytest.approx(1060.0, abs=1e-6), pytest.approx(640.0, abs=1e-6))


def test_silvera_checkerboard(fv):
    d = fv.Display.load("desktop-1080p")
    p = fv.CheckerboardPattern.from_acuity(4, d, fv.AcuityModel.preset("A"))
    deg = [math.degrees(math.atan(t / d.eye_distance_px())) for t in p.thresholds_px]
    assert deg[0] == pytest.approx(8.5, abs=0.05) and deg[2] == pytest.approx(12.2, abs=0.05)
    assert fv.checkerboard_sampling_factor(1) == pytest.approx(math.sqrt(4 / 3))
    assert fv.checkerboard_gap_px(1, 4) == 5.0
    assert fv.checkerboard_gap_px(3, 4) == pytest.approx(5 * math.sqrt(2))
    gaze = (960.0, 540.0)
    assert p.region(gaze, gaze) == 0 and p.kept((961.0, 541.0), gaze)
    assert p.region((10.0, 10.0), gaze) == 3
    f = fv.CheckerboardPattern.from_fractions(16, 1920, 1080)
    assert f.thresholds_px[0] == pytest.approx(0.10 * math.hypot(1920, 1080))


def test_techniques_and_their_derived_defaults(fv):
    ts = {t["name"]: t for t in fv.techniques()}
    builtin = ["native", "layered", "logpolar", "checkerboard", "lodmask", "inset", "vrs"]
    assert builtin + ["marwarp"] == list(ts)
    layers = next(p for p in ts["layered"]["params"] if p["key"] == "layers")
    assert (layers["min"], layers["max"], layers["default"], layers["type"]) == (1, 6, 2, "integer")
    assert ts["lodmask"]["needs_meshes"]
    # A parameter of listed values says which (edge_samples: 2 or 4; two
    # for vrs, four for marwarp).
    edges = next(p for p in ts["vrs"]["params"] if p["key"] == "edge_samples")
    assert (edges["allowed"], edges["default"]) == ([2.0, 4.0], 2)
    edges = next(p for p in ts["marwarp"]["params"] if p["key"] == "edge_samples")
    assert edges["default"] == 4
    assert layers["allowed"] == []
    # Each technique's planning margin comes first; logpolar's sigma at
    # 1920x1080 is derived for it (1.99 at the paper's plan, margin 1; 1.28
    # at its own 1.5).
    margin = ts["logpolar"]["params"][0]
    assert margin["key"] == "margin" and margin["default"] == 1.5
    sigma = next(p for p in ts["logpolar"]["params"] if p["key"] == "sigma")
    assert 1.0 <= sigma["default"] < 1.99
