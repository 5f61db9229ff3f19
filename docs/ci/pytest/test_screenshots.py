"""Screenshot tests in pytest with the shadelab module (docs/ci.md, "pytest"): each case is rendered
in-process and compared with references/NAME.png as `shadelab --reference` compares (max 4/255 per
channel, mean 0.002). A case that differs leaves its image and the amplified difference in pytest's
tmp_path and names them; `pytest --update` rewrites the references of the failing cases."""
import pathlib

import pytest

import shadelab

REFERENCES = pathlib.Path(__file__).parent / "references"

CASES = {
    "compare-ke128": dict(size=(240, 120), layout="compare", ke=128),
    "gouraud-misses-highlight": dict(scene=shadelab.data_path("scenes/lecture/03-gouraud-misses-highlight.json"),
                                     size=(240, 120)),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_screenshot(name, request, tmp_path):
    options = dict(CASES[name])
    image = shadelab.render(options.pop("scene", None), **options)
    reference = REFERENCES / (name + ".png")
    update = request.config.getoption("--update")
    if not reference.exists():
        if not update:
            pytest.fail(f"{reference} does not exist: pytest --update writes it from this render")
        shadelab.write_png(reference, image)
        pytest.skip(f"--update: wrote {reference}")
    result = shadelab.compare(image, reference)
    if not result and update:
        shadelab.write_png(reference, image)
        pytest.skip(f"--update: rewrote {reference} ({result.message})")
    if not result:
        shadelab.write_png(tmp_path / "actual.png", image)
        if result.difference is not None:
            shadelab.write_png(tmp_path / "difference.png", result.difference)
    assert result, f"{name}: {result.message}; this render and the difference are in {tmp_path}"
