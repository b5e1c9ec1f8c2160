# The image metrics on numpy arrays, and clear errors for arrays that are not images.
import math

import numpy as np
import pytest


def texture(h=48, w=64, seed=3):
    rng = np.random.default_rng(seed)
    small = rng.integers(0, 256, size=(h // 4, w // 4, 3), dtype=np.uint8)
    return np.kron(small, np.ones((4, 4, 1), dtype=np.uint8))  # 4x4 blocks


def srgb_to_linear(c):
    c = c / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def test_ssim_and_psnr(fv):
    img = texture()
    assert fv.ssim(img, img) == pytest.approx(1.0)
    shifted = np.roll(img, 2, axis=1)
    assert fv.ssim(img, shifted) < 0.9
    assert fv.psnr(img, img) == math.inf
    # MSE 100 over every channel: PSNR = 10 log10(255^2 / 100).
    a = np.zeros((8, 8, 3), np.uint8)
    b = np.full((8, 8, 3), 10, np.uint8)
    assert fv.mse(a, b) == pytest.approx(100.0)
    assert fv.psnr(a, b) == pytest.approx(10 * math.log10(255**2 / 100))
    m = fv.ssim_map(img, shifted)
    assert m.shape == (48, 64) and m.dtype == np.float32
    assert float(m.mean()) == pytest.approx(fv.ssim(img, shifted), rel=1e-5)


def test_float_and_rgba_inputs_mean_the_same(fv):
    img = texture()
    rgba = np.concatenate([img, np.full(img.shape[:2] + (1,), 7, np.uint8)], axis=2)
    shifted = np.roll(img, 1, axis=0)
    ref = fv.ssim(img, shifted)
    assert fv.ssim(img.astype(np.float32) / 255.0, shifted) == pytest.approx(ref)
    assert fv.ssim(rgba, shifted) == pytest.approx(ref)  # alpha ignored
    assert fv.ssim(np.asfortranarray(img), shifted) == pytest.approx(ref)  # any memory layout


def test_luminance_codes_of_grey_are_the_grey(fv):
    grey = np.full((4, 4, 3), 118, np.uint8)
    np.testing.assert_allclose(fv.luminance_codes(grey), 118.0, atol=0.01)


def test_compare_reports_every_metric(fv):
    ref = np.full((36, 64, 3), 200, np.uint8)
    test = np.full((36, 64, 3), 100, np.uint8)
    same = fv.compare(ref, ref)
    assert same["identical"] and same["psnr_db"] is None and same["ssim"] == pytest.approx(1.0)
    assert same["jnd_mean"] == 0.0
    r = fv.compare(ref, test, display="desktop-1080p", gaze=(32, 18))
    assert r["width"] == 64 and r["height"] == 36
    assert r["luminance_ratio"] == pytest.approx(srgb_to_linear(100) / srgb_to_linear(200), rel=0.01)
    assert r["psnr_db"] == pytest.approx(10 * math.log10(255**2 / 100**2))
    assert [b["from_deg"] for b in r["bands"]] == [0, 5, 10, 20]
    assert r["jnd_mean"] > 1.0 and r["visible_fraction"] == 1.0
    assert 0 < r["flip_mean"] <= 1
    assert fv.compare(ref, test, flip=False)["flip_mean"] is None


def test_maps_follow_the_geometry(fv):
    d = fv.Display.load("desktop-1080p")
    e = fv.eccentricity_map(d, 64, 36)
    assert e.shape == (36, 64)
    small = d.resized(64, 36)
    assert float(e[0, 0]) == pytest.approx(small.eccentricity_deg((0.5, 0.5), (32, 18)), rel=1e-5)
    assert float(e.min()) == pytest.approx(small.eccentricity_deg((32.5, 18.5), (32, 18)), rel=1e-5)
    img = texture()
    np.testing.assert_array_equal(fv.jnd_map(img, img), 0.0)
    np.testing.assert_allclose(fv.acuity_difference(img, img), 0.0, atol=1e-4)
    blurred = fv.acuity_filtered(img)
    assert blurred.shape == (48, 64)
    flip = fv.flip_map(img, np.roll(img, 3, axis=1), 40.0)
    assert flip.shape == (48, 64) and 0 <= float(flip.min()) and float(flip.max()) <= 1
    csf = fv.barten_csf(np.array([1.0, 4.0, 30.0]))
    assert csf[1] > csf[0] and csf[1] > csf[2]  # band-pass, peaking at a few cycles per degree
    assert fv.acuity_response(0.1, 1.0) == pytest.approx(1.0)


def test_bad_arrays_raise_clear_errors(fv):
    img = texture()
    with pytest.raises(ValueError, match=r"test: expected shape \(H, W, 3\) or \(H, W, 4\) \(sRGB\), got \(48, 64\)"):
        fv.ssim(img, img[:, :, 0])
    with pytest.raises(ValueError, match=r"got \(48, 64, 2\)"):
        fv.psnr(img[:, :, :2], img)
    with pytest.raises(TypeError, match="expected dtype uint8 \\(0..255\\) or float \\(0..1\\), got int32"):
        fv.ssim(img.astype(np.int32), img)
    with pytest.raises(TypeError, match="reference: expected a numpy array"):
        fv.ssim([[1, 2, 3]], img)
    with pytest.raises(ValueError, match=r"reference: float values must be sRGB in \[0, 1\], got 248 at \[0, 0, 0\]"):
        fv.ssim(img.astype(np.float64), img)
    with pytest.raises(ValueError, match=r"float values must be sRGB in \[0, 1\], got nan"):
        fv.ssim(np.full((4, 4, 3), np.nan), np.zeros((4, 4, 3)))
    with pytest.raises(ValueError, match=r"differs from the reference's \(48, 64\)"):
        fv.ssim(img, img[:40])
    with pytest.raises(TypeError, match="gaze: expected \\(x, y\\)"):
        fv.compare(img, img, gaze=(1, 2, 3))
    with pytest.raises(fv.Error, match="nope"):
        fv.compare(img, img, display="nope")


def test_fvvdp_images_and_sequences(fv):
    # FovVideoVDP: 10 JOD for identical inputs, lower with noise, lower still
    # where the viewer looks at the noise; sequences as FxHxWxC.
    ref = texture(96, 160)
    assert fv.fvvdp(ref, ref)["jod"] == 10.0
    rng = np.random.default_rng(5)
    noisy = np.clip(ref.astype(np.int16) + rng.integers(-12, 13, ref.shape), 0, 255).astype(np.uint8)
    r = fv.fvvdp(noisy, ref, display="desktop-1080p")
    assert 0 < r["jod"] < 10 and r["image"] and r["frames"] == 1
    assert r["photometry"]["peak_cd_m2"] == 200 and len(r["bands"]) == 4
    half = ref.copy()
    half[:, 80:] = noisy[:, 80:]
    on = fv.fvvdp(half, ref, gaze=(140, 48))["jod"]
    away = fv.fvvdp(half, ref, gaze=(5, 48))["jod"]
    assert on < away
    seq_ref = np.stack([np.roll(ref, i, axis=1) for i in range(5)])
    seq_test = np.stack([np.roll(noisy, i, axis=1) for i in range(5)])
    s = fv.fvvdp(seq_test, seq_ref, fps=30, gaze=np.array([[80.0, 48.0]] * 5), heatmap=True)
    assert not s["image"] and s["frames"] == 5 and s["fps"] == 30 and len(s["frame_jod"]) == 5
    assert s["heatmap"].shape == (96, 160) and s["heatmap"].dtype == np.float32
    assert fv.fvvdp(seq_ref, seq_ref)["jod"] == 10.0


def test_fvvdp_errors_name_the_input(fv):
    ref = texture(48, 64)
    with pytest.raises(ValueError, match="2 frames, reference 1"):
        fv.fvvdp(np.stack([ref, ref]), ref)
    with pytest.raises(ValueError, match="one point per frame"):
        fv.fvvdp(np.stack([ref, ref]), np.stack([ref, ref]), gaze=np.zeros((3, 2)))
    with pytest.raises(fv.Error, match="fvvdp.fps"):
        fv.fvvdp(np.stack([ref, ref]), np.stack([ref, ref]), fps=0)
