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


def configure_probe(tmp_path, links, sources=None, folders=()):
    """Configures a project of empty libraries with the project's layers and `links`
    ({library: [libraries it links]}); each library ari_X compiles src/X/x.cpp unless `sources`
    ({library: [files]}) says otherwise, and `folders` are made in src/ besides. Returns (exit
    code, output)."""
    sources = sources or {}
    lines = ["cmake_minimum_required(VERSION 3.16)", "project(layer_probe CXX)",
             "include(%s)" % LAYERS_CMAKE]
    for library in links:
        files = sources.get(library, ["src/%s/x.cpp" % library[len("ari_"):]])
        for name in files:
            (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
            (tmp_path / name).write_text("int %s_probe;\n" % library)
        lines.append("add_library(%s STATIC %s)" % (library, " ".join(files)))
    for folder in folders:
        (tmp_path / "src" / folder).mkdir(parents=True, exist_ok=True)
    for library, linked in links.items():
        if linked:
            lines.append("target_link_libraries(%s PUBLIC %s)" % (library, " ".join(linked)))
    lines.append("ari_check_layers()")
    (tmp_path / "CMakeLists.txt").write_text("\n".join(lines) + "\n")
    run = subprocess.run(["cmake", "-S", str(tmp_path), "-B", str(tmp_path / "build")],
                         capture_output=True, text=True)
    return run.returncode, " ".join((run.stdout + run.stderr).split())


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
            "it, engine") in output


def test_a_library_without_a_layer_stops_the_configure_step(tmp_path):
    code, output = configure_probe(tmp_path, dict(SOUND, ari_gadget=["ari_core"]))
    assert code != 0
    assert "library ari_gadget is in no layer" in output


def test_a_source_outside_its_library_folder_stops_the_configure_step(tmp_path):
    code, output = configure_probe(tmp_path, SOUND, sources={
        "ari_world": ["src/world/x.cpp", "src/model/borrowed.cpp"]})
    assert code != 0
    assert "ari_world compiles src/model/borrowed.cpp, which is library ari_model's folder" in output


def test_a_folder_without_its_library_stops_the_configure_step(tmp_path):
    code, output = configure_probe(tmp_path, SOUND, folders=["gadgets"])
    assert code != 0
    assert "src/gadgets/ or include/ari_social_sim/gadgets/ builds no library ari_gadgets" in output


def test_the_program_folders_need_no_library(tmp_path):
    code, output = configure_probe(tmp_path, SOUND, folders=["nodes", "tools", "python"])
    assert code == 0, output


def test_each_folder_of_the_repository_is_one_library():
    """The real tree: every folder of src/ but the programs' names a library of the layer table,
    and the headers' folders are the same set."""
    order, members = cmake_layers()
    libraries = {lib[len("ari_"):] for layer in order for lib in members[layer]}
    programs = {"nodes", "tools", "python"}
    folders = {d.name for d in (ROOT / "src").iterdir() if d.is_dir()}
    assert folders - programs == libraries
    headers = {d.name for d in (ROOT / "include" / "ari_social_sim").iterdir() if d.is_dir()}
    assert headers <= libraries


if __name__ == "__main__":
    raise SystemExit(pytest.main([__file__, "-q"]))
