"""The configure-time layer check (cmake/layers.cmake): its table agrees with
docs/ARCHITECTURE.md's, and on a small probe project it passes the real layering and stops at an
upward link or a library without a layer, naming them."""
import pathlib
import re
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
LAYERS_CMAKE = ROOT / "cmake" / "layers.cmake"


def cmake_layers():
    text = LAYERS_CMAKE.read_text()
    order = re.search(r"set\(ari_layers ([^)]*)\)", text).group(1).split()
    members = {}
    for name in order:
        body = re.search(r"set\(ari_layer_%s\s([^)]*)\)" % name, text).group(1)
        members[name] = body.split()
    return order, members


def documented_layers():
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text()
    section = text[text.index("### Layers"):]
    rows = re.findall(r"^\| ([a-z_]+) \| (ari_[a-z_, ]+) \|$", section, re.MULTILINE)
    return [name for name, _ in rows], {name: libs.split(", ") for name, libs in rows}


def test_the_documented_layers_are_the_configured_ones():
    assert documented_layers() == cmake_layers()


def configure_probe(tmp_path, links):
    """Configures a project of empty libraries with the project's layers and `links`
    ({library: [libraries it links]}); returns (exit code, output)."""
    (tmp_path / "empty.c").write_text("int probe;\n")
    lines = ["cmake_minimum_required(VERSION 3.16)", "project(layer_probe C)",
             "include(%s)" % LAYERS_CMAKE]
    for library in links:
        lines.append("add_library(%s STATIC empty.c)" % library)
    for library, linked in links.items():
        if linked:
            lines.append("target_link_libraries(%s PUBLIC %s)" % (library, " ".join(linked)))
    lines.append("ari_check_layers()")
    (tmp_path / "CMakeLists.txt").write_text("\n".join(lines) + "\n")
    run = subprocess.run(["cmake", "-S", str(tmp_path), "-B", str(tmp_path / "build")],
                         capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


SOUND = {"ari_core": [], "ari_model": ["ari_core"], "ari_world": ["ari_model"],
         "ari_navigation": ["ari_model"], "ari_scenario": ["ari_world", "ari_navigation"]}


def test_the_real_layering_passes(tmp_path):
    code, output = configure_probe(tmp_path, SOUND)
    assert code == 0, output
    assert "every library links only its own layer and those below" in output


def test_an_upward_link_stops_the_configure_step(tmp_path):
    code, output = configure_probe(tmp_path, dict(SOUND, ari_navigation=["ari_model",
                                                                         "ari_scenario"]))
    print(output)
    assert code != 0
    assert ("ari_navigation (layer simulation) links ari_scenario, which is in the layer above "
            "it, engine") in " ".join(output.split())


def test_a_library_without_a_layer_stops_the_configure_step(tmp_path):
    code, output = configure_probe(tmp_path, dict(SOUND, ari_gadget=["ari_core"]))
    assert code != 0
    assert "library ari_gadget is in no layer" in " ".join(output.split())


if __name__ == "__main__":
    raise SystemExit(pytest.main([__file__, "-q"]))
