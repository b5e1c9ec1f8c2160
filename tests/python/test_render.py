# foveate.render(), the module's defaults against the command's, the notes a
# run gives, and the module's import under another interpreter.
import os
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest


def test_render_returns_the_frames_as_numpy_arrays(fv):
    r = fv.render(scene="cheap", technique="layered", size=(64, 36), frames=2)
    assert len(r["frames"]) == 2
    for f in r["frames"]:
        assert isinstance(f, np.ndarray) and f.shape == (36, 64, 3) and f.dtype == np.uint8
    assert len(r["shaded_pixels"]) == 2 and r["native_pixels"] == [64 * 36, 64 * 36]
    assert "2 frames" in r["gaze_report"]
    native = fv.render(scene="cheap", size=(64, 36))
    assert len(native["frames"]) == 1 and native["shaded_pixels"] == [64 * 36]


def test_render_refuses_what_the_command_refuses(fv):
    with pytest.raises(fv.Error, match="gaze.*outside the 64x36 image"):
        fv.render(scene="cheap", size=(64, 36), gaze="5000,100")
    with pytest.raises(fv.Error, match="1.5 is outside 0.0..1.0"):
        fv.render(scene="cheap", size=(64, 36), gaze="1.5,0.5")
    with pytest.raises(fv.Error, match="logpolar.sigma: logpolar is not among the techniques run"):
        fv.render(scene="cheap", technique="layered", size=(64, 36), params={"logpolar.sigma": 2})
    with pytest.raises(fv.Error, match="did you mean 'layered'"):
        fv.render(scene="cheap", technique="layerd", size=(64, 36))


def test_a_size_with_little_to_save_is_noted(fv):
    with pytest.warns(UserWarning, match="little or nothing to save"):
        r = fv.render(scene="cheap", technique="layered", size=(64, 36))
    assert any("little or nothing to save" in n for n in r["notes"])
    with pytest.warns(UserWarning, match="little or nothing to save"):
        b = fv.bench(scene="cheap", techniques=["layered"], size=(64, 36), frames=1, warmup=0,
                     metrics=False)
    assert b["savings"]["little_to_save"] and b["savings"]["pixel_bound"] < 1.5


def test_bench_refuses_a_parameter_of_a_technique_not_run(fv):
    with pytest.raises(fv.Error, match="logpolar.sigma: logpolar is not among the techniques run"):
        fv.bench(scene="cheap", techniques=["layered"], size=(64, 36), frames=1,
                 params={"logpolar.sigma": 2})


def keyword_defaults(fn):
    """The keyword defaults in a pybind11 function's signature line."""
    sig = fn.__doc__.splitlines()[0]
    return dict(re.findall(r"(\w+): [^=,]+ = ('[^']*'|[^,)]+)", sig))


@pytest.mark.skipif(not os.environ.get("FOVEATE"), reason="FOVEATE (the command) not set")
def test_the_defaults_are_the_commands():
    import foveate as fv

    help_text = subprocess.run([os.environ["FOVEATE"], "bench", "--help"], capture_output=True,
                               text=True, check=True).stdout
    # CLI11 writes an option's default as "--scene TEXT=raymarch".
    command = dict(re.findall(r"--([a-z-]+) [A-Z]+=(\S+)", help_text))
    module = {k: v.strip("'") for k, v in keyword_defaults(fv.bench).items()}
    for key in ("scene", "size", "frames", "warmup", "display", "fps", "reference"):
        assert key in command, f"foveate bench --help shows no default for --{key}"
        assert float(module[key]) == float(command[key]) if key == "fps" else \
            module[key] == command[key], f"{key}: module {module[key]}, command {command[key]}"
    render_defaults = {k: v.strip("'") for k, v in keyword_defaults(fv.render).items()}
    assert render_defaults["scene"] == command["scene"]
    assert render_defaults["size"] == command["size"]


def test_another_interpreter_is_told_which_one_the_module_needs():
    # An interpreter without numpy, as another one on the machine may be.
    code = "import sys; sys.modules['numpy'] = None\nimport foveate"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=dict(os.environ))
    assert r.returncode != 0
    assert "ImportError" in r.stderr
    assert "this module was built for" in r.stderr and "with numpy" in r.stderr, r.stderr
    assert "numpy cannot be imported in " + sys.executable in r.stderr, r.stderr


def test_bench_refuses_an_out_folder_holding_another_run(fv, tmp_path):
    args = dict(scene="cheap", techniques=["layered"], size=(32, 18), frames=1, warmup=0,
                metrics=False, out=str(tmp_path))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fv.bench(**args)
        with pytest.raises(fv.Error, match="holds the output of an earlier run.*overwrite=True"):
            fv.bench(**args)
        (tmp_path / "results.md").unlink()
        (tmp_path / "stale-notes.txt").write_text("mine")
        fv.bench(**args, overwrite=True)
    assert (tmp_path / "results.md").exists() and (tmp_path / "stale-notes.txt").exists()


def test_a_scenes_load_warning_is_a_python_warning(fv):
    # A Shadertoy file sampling a channel bound to nothing: the scene's warning
    # reaches Python as a UserWarning and the result's notes, not stderr alone.
    import pathlib

    shader = pathlib.Path(__file__).parents[1] / "data" / "shadertoy" / "unbound_channel.glsl"
    with pytest.warns(UserWarning, match="samples iChannel1 but no image or buffer is bound"):
        r = fv.render(scene=str(shader), size=(64, 36))
    assert any("iChannel1" in n for n in r["notes"])
    # Each render loads the scene again and says it again, once.
    with pytest.warns(UserWarning, match="samples iChannel1"):
        again = fv.render(scene=str(shader), size=(64, 36))
    assert sum("iChannel1" in n for n in again["notes"]) == 1
