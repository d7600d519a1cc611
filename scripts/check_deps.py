#!/usr/bin/env python3
"""Fails when the build, the nodes, the tools or the tests use a Debian package that
scripts/install_deps.sh does not install, directly or as a dependency; and when an optional Python
import (guarded by `except ImportError`) comes from a package that neither it nor
scripts/install_extras.sh installs.

A machine that already has a package hides its absence from install_deps.sh: CI once stayed green
without libnlopt-dev while a fresh machine failed. So this looks at what was really used: the
compiler's dependency files, CMakeCache.txt and the link commands, ldd of the built binaries, the
project's Python imports, and the programs that the shell scripts, launch files and test targets
run. Each file is mapped to its Debian package with dpkg -S and must be in the Depends and
Pre-Depends closure of install_deps.sh's list (not Recommends: install_deps.sh installs without
them), or be Essential or Priority: required, which every Debian has.

usage: /usr/bin/python3 scripts/check_deps.py [--repo DIR] [--build DIR] [--without PKG]...
                                              [--self-test]
"""

import argparse
import ast
import glob
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

DEBIAN_PYTHON = "/usr/bin/python3"
PROJECT_PACKAGE = "ari_social_sim"
# Never from a package, and nothing a fresh machine needs to have.
TRANSIENT_ROOTS = ("/tmp", "/proc")
# Where the project's scripts, tests, benchmarks and sources are (its Python and #! scripts).
PROJECT_CODE_FOLDERS = ("scripts", "test", "bench", "src")
# prepare.sh and the screenshot scripts put Debian's /usr/bin first: their commands resolve so.
SCRIPT_PATH = "/usr/bin:" + os.environ.get("PATH", "")

# Entries of install_deps.sh that the self-test removes one at a time: the check must then fail and
# name it. libnlopt-dev is the one install_deps.sh once forgot; the others are found by other
# routes (Box2D's headers and library, yaml-cpp's headers, the screenshot scripts' ImageMagick,
# the Python module's pybind11 headers, the data converter's scipy import (which brings numpy), the
# Haar cascade the detector study names).
SELF_TEST_REMOVALS = ("libnlopt-dev", "libbox2d-dev", "libyaml-cpp-dev", "imagemagick",
                      "pybind11-dev", "python3-scipy", "opencv-data")

# Debian package of install_deps.sh -> the rosdep keys that install it (rosdistro's
# rosdep/base.yaml, debian; octomap and urdfdom are also ROS packages whose package.xml Debian
# ships). Only keys known for sure: package.xml must name one key of each of these it installs.
ROSDEP_KEYS = {
    "libbenchmark-dev": ("benchmark",),
    "libbox2d-dev": ("box2d-dev",),
    "libbullet-dev": ("bullet",),
    "libeigen3-dev": ("eigen",),
    "libgtest-dev": ("gtest",),
    "libnlopt-dev": ("libnlopt-dev",),
    "liboctomap-dev": ("liboctomap-dev", "octomap"),
    "libopencv-dev": ("libopencv-dev",),
    "liburdfdom-dev": ("liburdfdom-dev", "urdfdom"),
    "libyaml-cpp-dev": ("yaml-cpp",),
    "pybind11-dev": ("pybind11-dev",),
    "python3-numpy": ("python3-numpy",),
    "python3-pytest": ("python3-pytest",),
    "python3-scipy": ("python3-scipy",),
    "curl": ("curl",),
}
PACKAGE_XML_DEPENDS = ("buildtool_depend", "depend", "build_depend", "exec_depend", "test_depend")


def report(line):
    print(f"check_deps: {line}", flush=True)


def read(path):
    with open(path, errors="replace") as stream:
        return stream.read()


# ---------------------------------------------------------------------------------------------
# What the build, the tools and the tests used: files, each with the first reason it was seen.


class Usage:
    def __init__(self, repo, build):
        sources = cmake_cache_value(build, "CMAKE_HOME_DIRECTORY")  # the build's own source tree
        roots = tuple(os.path.realpath(root) for root in (repo, build, sources))
        self.own_roots = roots + TRANSIENT_ROOTS
        self.files = {}     # path -> why it counts as used
        self.optional = {}  # path -> why: optional imports, from install_extras.sh or the main list
        self.problems = []  # what was used but could not be found at all

    def use(self, path, why):
        if not any(path == root or path.startswith(root + "/") for root in self.own_roots):
            self.files.setdefault(path, why)


def cmake_cache_value(build, name):
    cache = read(os.path.join(build, "CMakeCache.txt"))
    return re.search(rf"(?m)^{name}:\w+=(.*)$", cache).group(1)


def make_prerequisites(depfile):
    """Absolute paths in a make-style dependency file (escaped spaces, continued lines)."""
    text = re.sub(r"(?m)^#.*$", "", read(depfile)).replace("\\\n", " ")
    for token in re.findall(r"(?:\\ |\S)+", text):
        token = token.replace("\\ ", " ").rstrip(":")
        if token.startswith("/"):
            yield os.path.normpath(token)


def collect_compiler_dependencies(build, usage):
    depfiles = [os.path.join(folder, name) for folder, _, names in os.walk(build) for name in names
                if name.endswith(".o.d") or name in ("compiler_depend.make", "depend.make")]
    if not depfiles:
        usage.problems.append(f"no compiler dependency files under {build}: build first")
    for depfile in depfiles:
        for path in make_prerequisites(depfile):
            usage.use(path, "a header of the build")


def collect_cmake_cache(build, usage):
    """Files CMake found: programs, and for a package folder its config files (what find_package
    read; a folder such as /usr/include belongs to many packages, and the headers used from it are
    in the dependency files). Libraries count when a link command uses them, not when merely
    cached: FindOpenGL caches GLU and GLX although nothing links them."""
    cache = read(os.path.join(build, "CMakeCache.txt"))
    values = re.findall(r"(?m)^\w+_(?:DIR|INCLUDE_DIR|EXECUTABLE):\w+=(.+)$", cache)
    for path in (path for value in values for path in value.split(";")):
        if os.path.isfile(path):
            usage.use(path, "found by CMake (CMakeCache.txt)")
        elif os.path.isdir(path):
            for config in glob.glob(os.path.join(glob.escape(path), "*[Cc]onfig.cmake")):
                usage.use(config, "read by find_package (CMakeCache.txt)")


def collect_link_commands(build, usage):
    """Libraries given to the linker by path (CMakeFiles/*.dir/link.txt)."""
    pattern = os.path.join(glob.escape(build), "**", "CMakeFiles", "*.dir", "link.txt")
    for link_file in glob.glob(pattern, recursive=True):
        for token in read(link_file).split():
            if token.startswith("/") and os.path.isfile(token):
                usage.use(token, "linked by the build (link.txt)")


def is_elf(path):
    with open(path, "rb") as stream:
        return stream.read(4) == b"\x7fELF"


def built_binaries(build):
    files = (os.path.join(folder, name) for top in ("devel/lib", "bench")
             for folder, _, names in os.walk(os.path.join(build, top)) for name in names)
    return sorted(path for path in files if not os.path.islink(path) and is_elf(path))


def needed_sonames(library, cache={}):
    """The sonames `library` needs, directly or not (ldd), cached."""
    if library not in cache:
        output = subprocess.run(["ldd", library], capture_output=True, text=True).stdout
        cache[library] = {line.split(" => ")[0].strip()
                          for line in output.splitlines() if " => /" in line}
    return cache[library]


def collect_linked_libraries(build, usage):
    binaries = built_binaries(build)
    if not binaries:
        usage.problems.append(f"no built binaries under {build}/devel/lib: build first")
        return
    # The devel space's own libraries resolve as they do once setup.bash is sourced.
    library_path = os.path.join(build, "devel", "lib") + ":" + os.environ.get("LD_LIBRARY_PATH", "")
    output = subprocess.run(["ldd", *binaries], capture_output=True, text=True,
                            env=dict(os.environ, LD_LIBRARY_PATH=library_path)).stdout
    binary = binaries[0]  # ldd names each binary only when given several
    linked = []  # (binary, soname, library path)
    for line in output.splitlines():
        if not line.startswith("\t"):
            binary = line.rstrip(":")
            continue
        name, arrow, target = line.strip().partition(" => ")
        if target.startswith("not found"):
            usage.problems.append(f"{binary} needs {name}, which is not installed")
        path = (target if arrow else name).split(" (")[0]  # else: the loader, or linux-vdso
        if path.startswith("/"):
            linked.append((binary, name, path))
    # A library reached through update-alternatives (libblas.so.3) brings what the chosen
    # implementation links and the others do not (OpenBLAS's libopenblas.so.0): this machine's
    # choice, not a need of the build. The alternative itself still counts (alternatives_of).
    choice_only = set()  # sonames
    for path in {path for _, _, path in linked}:
        files = [file for file in alternatives_of(path) if os.path.exists(file)]
        if files:
            needs = [needed_sonames(file) for file in files]
            choice_only |= needed_sonames(os.path.realpath(path)) - set.intersection(*needs)
    for binary, name, path in linked:
        if name not in choice_only:
            usage.use(path, f"linked by {os.path.basename(binary)}")


def collect_test_target_programs(build, usage):
    """Programs the run_tests targets run (python3, catkin's run_tests.py, rostest)."""
    pattern = os.path.join(glob.escape(build), "CMakeFiles", "run_tests*", "build.make")
    for makefile in glob.glob(pattern):
        commands = " ".join(line for line in read(makefile).splitlines() if line.startswith("\t"))
        for token in commands.replace('"', " ").replace("\\", " ").split():
            if token.startswith("/") and os.path.isfile(token):
                usage.use(token, "run by the run_tests targets")


# --- the project's own files ------------------------------------------------------------------


def project_files(repo):
    for top in PROJECT_CODE_FOLDERS:
        for folder, _, names in sorted(os.walk(os.path.join(repo, top))):
            yield from sorted(os.path.join(folder, name) for name in names)


def shell_scripts(repo):
    return sorted(glob.glob(os.path.join(repo, "scripts", "*.sh")))


HEREDOC = re.compile(r"<<-?\s*(['\"]?)(\w+)\1")


def shell_lines(text):
    """(line, here-document terminator or None, its body) for each line of a shell script that
    is not inside a here-document or a multi-line array literal."""
    lines, index = text.splitlines(), 0
    while index < len(lines):
        line = lines[index]
        index += 1
        if re.search(r"=\($", line.strip()):  # install_deps.sh's packages=( ... )
            while index < len(lines) and lines[index].strip() != ")":
                index += 1
            index += 1
            continue
        heredoc = HEREDOC.search(line)
        terminator, start = heredoc.group(2) if heredoc else None, index
        while terminator and index < len(lines) and lines[index].strip() != terminator:
            index += 1
        yield line, terminator, "\n".join(lines[start:index])
        index += 1 if terminator else 0


# --- Python -----------------------------------------------------------------------------------


def python_sources(repo):
    """(name, folder its own imports resolve from, source) of the project's Python, including
    the programs that shell scripts hand to python3 in here-documents (run from the repository)."""
    for path in (path for path in project_files(repo) if path.endswith(".py")):
        yield os.path.relpath(path, repo), os.path.dirname(path), read(path)
    for script in shell_scripts(repo):
        for line, terminator, body in shell_lines(read(script)):
            if terminator == "PY" or (terminator and "python" in line):
                yield f"{os.path.relpath(script, repo)} (here-document)", repo, body


def top_modules(node):
    if isinstance(node, ast.Import):
        yield from (alias.name.split(".")[0] for alias in node.names)
    elif isinstance(node, ast.ImportFrom) and node.level == 0:
        yield node.module.split(".")[0]


def catches_import_error(handler):
    names = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any(isinstance(name, ast.Name) and name.id in ("ImportError", "ModuleNotFoundError")
               for name in names)


def imported_modules(source):
    """(required, optional) top-level modules of a source. An import in the body of a `try:` whose
    handler catches ImportError is optional: the program runs without it (it tells the user to
    run scripts/install_extras.sh)."""
    tree = ast.parse(source)
    optional_nodes = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Try) and any(catches_import_error(h) for h in node.handlers):
            for statement in node.body:
                optional_nodes.update(id(inner) for inner in ast.walk(statement))
    required, optional = set(), set()
    for node in ast.walk(tree):
        (optional if id(node) in optional_nodes else required).update(top_modules(node))
    return required, optional - required


def module_file(name):
    """The file Debian's python3 imports for a top-level module, or None if it finds none."""
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return None
    if spec is None:
        return None
    if spec.origin in ("built-in", "frozen"):
        return os.path.realpath(sys.executable)  # compiled into the interpreter
    # A namespace package has no file: its folder stands for it.
    return spec.origin or list(spec.submodule_search_locations)[0]


def is_own_module(module, folder):
    """The package's generated messages, or a module beside the importing file."""
    return module == PROJECT_PACKAGE or os.path.exists(os.path.join(folder, module + ".py")) \
        or os.path.isdir(os.path.join(folder, module))


def collect_python_imports(repo, usage):
    for name, folder, source in python_sources(repo):
        required, optional = imported_modules(source)
        for module in sorted(required):
            if is_own_module(module, folder):
                continue
            path = module_file(module)
            if path is None:
                usage.problems.append(
                    f"{name} imports {module}, which Debian's python3 does not find")
            else:
                usage.use(path, f"python module {module}, imported by {name}")
        for module in sorted(optional):
            path = module_file(module)
            if path is not None and not is_own_module(module, folder):
                usage.optional.setdefault(path, f"optional python module {module}, imported by "
                                                f"{name}")


# --- programs the shell scripts run -----------------------------------------------------------

COMMAND_SEPARATORS = re.compile(r"\|\||&&|[|;&`]|\$\(")
PREFIX_WORDS = {"exec", "if", "then", "else", "elif", "while", "until", "do", "!", "time",
                "command"}


def first_words(line, not_programs):
    """Programs a shell line runs: the first word of each command, after keywords and variable
    assignments; `timeout N CMD` runs both timeout and CMD."""
    line = re.sub(r"(^|\s)#.*", "", line)
    line = re.sub(r"\d*>&\d*|&>", " ", line)  # 2>&1 is a redirection, not a separator
    for segment in COMMAND_SEPARATORS.split(line):
        words = segment.split()
        while words and (words[0] in PREFIX_WORDS or re.match(r"\w+=", words[0])):
            words.pop(0)
        if words and words[0] == "timeout":
            yield words.pop(0)
            words = words[1:]
        if words and is_program_word(words[0]) and words[0] not in not_programs:
            yield words[0]


def is_program_word(word):
    """A name or path, not an expansion, a quoted string or a number."""
    return re.fullmatch(r"[\w/][\w./+-]*", word) and re.search(r"[A-Za-z]", word)


def script_commands(repo):
    """(program, script) for each command line of scripts/*.sh (a line continued with a
    backslash carries arguments only), and the interpreter of each project file's #! line."""
    shell_words = subprocess.run(["bash", "-c", "compgen -k; compgen -b"],
                                 capture_output=True, text=True).stdout.split()
    for script in shell_scripts(repo):
        text = read(script)
        not_programs = {*shell_words, *re.findall(r"(?m)^\s*([\w-]+)\s*\(\)\s*\{", text)}
        continued = False
        for line, _, _ in shell_lines(text):
            if not continued:
                yield from ((word, script) for word in first_words(line, not_programs))
            continued = line.rstrip().endswith("\\")
    for path in project_files(repo):
        interpreter = shebang_interpreter(path)
        if interpreter:
            yield interpreter, path


def shebang_interpreter(path):
    with open(path, "rb") as stream:
        first = stream.readline(200).decode(errors="replace")
    words = first[2:].split() if first.startswith("#!") else []
    if words and os.path.basename(words[0]) == "env":
        words = words[1:]
    return words[0] if words else None


def program_path(program, repo):
    if "/" not in program:
        return shutil.which(program, path=SCRIPT_PATH)
    path = os.path.join(repo, program)  # relative: a project file, run from the repository's root
    return path if os.path.exists(path) else None


def collect_script_commands(repo, usage):
    for program, script in script_commands(repo):
        name = os.path.relpath(script, repo)
        path = program_path(program, repo)
        if path is None:
            usage.problems.append(f"{name} runs {program}, which is not installed")
        else:
            usage.use(path, f"run by {name}")


# --- other ROS packages the launch files use --------------------------------------------------


def collect_launch_programs(repo, usage):
    """Other ROS packages' nodes in launch and rostest files, and packages they $(find)."""
    launch_files = glob.glob(os.path.join(repo, "launch", "*.launch")) + \
        glob.glob(os.path.join(repo, "test", "**", "*.test"), recursive=True)
    for launch_file in sorted(launch_files):
        name = os.path.relpath(launch_file, repo)
        for element in ElementTree.parse(launch_file).getroot().iter():
            if element.tag in ("node", "test") and element.get("pkg") != PROJECT_PACKAGE:
                use_ros_package(element.get("pkg"), element.get("type"), name, usage)
        found = set(re.findall(r"\$\(find ([\w-]+)\)", read(launch_file)))
        for package in sorted(found - {PROJECT_PACKAGE}):
            use_ros_package(package, None, name, usage)


def use_ros_package(package, program, launch_file, usage):
    """Debian installs ROS package X's manifest as /usr/share/X/package.xml and its nodes in
    /usr/lib/X (catkin's libexec folder) or /usr/share/X."""
    manifest = f"/usr/share/{package}/package.xml"
    if not os.path.isfile(manifest):
        usage.problems.append(f"{launch_file} uses ROS package {package}, which is not installed")
        return
    usage.use(manifest, f"ROS package {package}, used by {launch_file}")
    if program is None:
        return
    found = [path for path in (f"/usr/lib/{package}/{program}", f"/usr/share/{package}/{program}")
             if os.path.isfile(path)]
    if not found:
        usage.problems.append(f"{launch_file} runs {package}/{program}, which is not installed")
    for path in found:
        usage.use(path, f"{package}/{program}, run by {launch_file}")


# An absolute path to a system data file written in the project's code, e.g. a stock classifier.
DATA_FILE_LITERAL = re.compile(r"[\"'](/usr/share/[^\"'\s{}]+\.[A-Za-z0-9]+)[\"']")


def collect_named_data_files(repo, usage):
    """Data files the code opens by absolute path at run time (Debian's opencv-data cascades):
    neither the compiler nor the linker sees them."""
    for path in project_files(repo):
        if not path.endswith((".cpp", ".hpp", ".py")):
            continue
        for data_file in sorted(set(DATA_FILE_LITERAL.findall(read(path)))):
            if os.path.exists(data_file):
                usage.use(data_file, f"named in {os.path.relpath(path, repo)}")
            else:
                usage.problems.append(f"{os.path.relpath(path, repo)} names {data_file}, which is "
                                      f"not installed")


def collect_usage(repo, build):
    usage = Usage(repo, build)
    collect_compiler_dependencies(build, usage)
    collect_cmake_cache(build, usage)
    collect_link_commands(build, usage)
    collect_linked_libraries(build, usage)
    collect_test_target_programs(build, usage)
    collect_python_imports(repo, usage)
    collect_script_commands(repo, usage)
    collect_launch_programs(repo, usage)
    collect_named_data_files(repo, usage)
    return usage


# ---------------------------------------------------------------------------------------------
# Debian: the installed packages, their dependencies, and who owns a file.


def relation_names(field):
    """'a (>= 1) | b:any, c' -> [['a', 'b'], ['c']]: the alternatives of each relation, without
    versions, architecture qualifiers or restrictions."""
    groups = (group.strip() for group in field.split(","))
    return [[re.split(r"[\s(\[<:]", alternative.strip())[0] for alternative in group.split("|")]
            for group in groups if group]


def merged_usr_twin(path):
    """/lib/x <-> /usr/lib/x: bookworm's packages list either spelling of a merged-/usr path."""
    for top in ("/bin/", "/sbin/", "/lib/", "/lib32/", "/lib64/", "/libx32/"):
        if path.startswith(top):
            return "/usr" + path
        if path.startswith("/usr" + top):
            return path[len("/usr"):]
    return None


def alternatives_of(path):
    """Every file the update-alternatives group that `path` leads through can point to (e.g.
    libblas.so.3: the reference BLAS or OpenBLAS), or [] when no link on its way is in
    /etc/alternatives. The group's link may point to whichever is installed, so any of them
    serves."""
    seen = set()
    while os.path.islink(path) and path not in seen:
        seen.add(path)
        target = os.path.join(os.path.dirname(path), os.readlink(path))
        if target.startswith("/etc/alternatives/"):
            listing = subprocess.run(["update-alternatives", "--list", os.path.basename(target)],
                                     capture_output=True, text=True).stdout
            files = listing.split()
            return files + [twin for twin in map(merged_usr_twin, files) if twin]
        path = target
    return []


class Dpkg:
    """The installed packages, and the owners of files: each asked of dpkg once per run."""

    def __init__(self):
        self.depends = {}    # installed package -> its Pre-Depends and Depends, as alternatives
        self.providers = {}  # virtual package -> the installed packages that provide it
        self.always = set()  # Essential: yes or Priority: required
        self.owners_of = {}  # path -> the packages that own it
        fields = "\t".join(("${Package}", "${db:Status-Abbrev}", "${Essential}", "${Priority}",
                            "${Pre-Depends}", "${Depends}", "${Provides}")) + "\n"
        output = subprocess.run(["dpkg-query", "-W", "-f", fields],
                                capture_output=True, text=True, check=True).stdout
        for line in output.splitlines():
            package, status, essential, priority, pre_depends, depends, provides = line.split("\t")
            if status[1:2] != "i":
                continue  # known to dpkg but not installed (removed, configuration files left)
            relations = relation_names(pre_depends) + relation_names(depends)
            self.depends.setdefault(package, []).extend(relations)
            for virtual in relation_names(provides):
                self.providers.setdefault(virtual[0], []).append(package)
            if essential == "yes" or priority == "required":
                self.always.add(package)

    def satisfier(self, alternatives):
        """What satisfies one relation here: its first installed alternative, as itself or
        through a package that provides it (apt, too, tries the first alternative first)."""
        for name in alternatives:
            if name in self.depends:
                return name
            if name in self.providers:
                return self.providers[name][0]
        return None

    def closure(self, packages):
        """The packages and everything they depend on (Pre-Depends, Depends), recursively."""
        seen, todo = set(), [self.satisfier([package]) for package in packages]
        while todo:
            package = todo.pop()
            if package is None or package in seen:
                continue
            seen.add(package)
            todo.extend(self.satisfier(alternatives) for alternatives in self.depends[package])
        return seen

    def owners(self, paths):
        """path -> its owners (dpkg -S). A path dpkg does not know is tried in its merged-/usr
        spelling, then as every file of the update-alternatives group it leads through, then as
        the file its symlinks lead to."""
        pending = {path for path in paths if path not in self.owners_of}
        for spellings in (lambda path: [path],
                          lambda path: [merged_usr_twin(path)],
                          alternatives_of,
                          lambda path: [os.path.realpath(path),
                                        merged_usr_twin(os.path.realpath(path))]):
            asked = {path: [name for name in spellings(path) if name] for path in pending}
            found = self.search({name for names in asked.values() for name in names})
            for path, names in asked.items():
                owners = sorted({owner for name in names for owner in found.get(name, ())})
                if owners:
                    self.owners_of[path] = owners
            pending -= set(self.owners_of)
        self.owners_of.update((path, []) for path in pending)
        return {path: self.owners_of[path] for path in paths}

    @staticmethod
    def search(paths):
        """dpkg-query -S, 500 paths a call. An absolute path without wildcards matches exactly."""
        found, paths = {}, sorted(path for path in paths if not re.search(r"[*?\[\\]", path))
        for start in range(0, len(paths), 500):
            output = subprocess.run(["dpkg-query", "-S", *paths[start:start + 500]],
                                    capture_output=True, text=True).stdout
            for line in output.splitlines():
                if line.startswith("diversion by"):
                    continue
                packages, _, path = line.partition(": ")
                found[path] = [package.strip().split(":")[0] for package in packages.split(",")]
        return found


# ---------------------------------------------------------------------------------------------
# The check.


def install_script_packages(repo, script_name):
    """The entries of an install script's packages=( ... ) array, comments left out."""
    script = re.sub(r"#.*", "", read(os.path.join(repo, "scripts", script_name)))
    match = re.search(r"(?ms)^packages=\((.*?)\)", script)
    if not match:
        sys.exit(f"check_deps: scripts/{script_name} has no packages=( ... ) array")
    return match.group(1).split()


def install_deps_packages(repo):
    return install_script_packages(repo, "install_deps.sh")


class UsedPackages:
    """The Debian packages the used files belong to, each with a file that shows it is used."""

    def __init__(self, usage, dpkg):
        self.example = {}     # package -> one of its files that was used, and why
        self.candidates = []  # (file, owners) of files several packages own: any owner will do
        self.problems = list(usage.problems)
        for path, owners in sorted(dpkg.owners(list(usage.files)).items()):
            if not owners:
                self.problems.append(f"not from any Debian package: {path} ({usage.files[path]})")
            elif len(owners) == 1:
                self.example.setdefault(owners[0], f"{path}: {usage.files[path]}")
            else:
                self.candidates.append((path, owners))

    def packages(self):
        return set(self.example) | {owners[0] for _, owners in self.candidates}

    def missing(self, allowed):
        """(package, example) for each used package outside `allowed`."""
        missing = {package: example for package, example in self.example.items()
                   if package not in allowed}
        for path, owners in self.candidates:
            if not allowed.intersection(owners):
                missing.setdefault(owners[0], path)
        return sorted(missing.items())


def check(used, dpkg, listed):
    """([problem lines], size of the closure of `listed`), `listed` standing for install_deps.sh's
    list."""
    listed_closure = dpkg.closure(listed)
    allowed = listed_closure | dpkg.closure(dpkg.always)
    lines = used.problems + [f"{package} is used (e.g. {example}) but scripts/install_deps.sh does "
                             f"not install it" for package, example in used.missing(allowed)]
    return lines, len(listed_closure)


def run_check(used, dpkg, listed):
    lines, closure_size = check(used, dpkg, listed)
    for line in lines:
        report(line)
    if not lines:
        report(f"{len(used.packages())} packages used by the build, tools and tests, all installed "
               f"by scripts/install_deps.sh (closure of {closure_size} packages)")
    return not lines


def run_self_test(used, dpkg, listed):
    """Each removal must make the check fail, naming the removed package or a package that only
    it brought in. Runs on the usage already collected: only the list changes."""
    passed = True
    for removed in SELF_TEST_REMOVALS:
        if removed not in listed:
            report(f"self-test: FAILED: {removed} is not in scripts/install_deps.sh's list")
            passed = False
            continue
        remaining = [package for package in listed if package != removed]
        only_through_it = dpkg.closure(listed) - dpkg.closure(remaining)
        lines, _ = check(used, dpkg, remaining)
        named = sorted(package for package in only_through_it
                       if any(line.startswith(package + " is used") for line in lines))
        if named:
            report(f"self-test: without {removed} the check fails, naming {', '.join(named)}")
        else:
            report(f"self-test: FAILED: without {removed} the check does not name it")
            passed = False
    return passed


def check_optional(usage, dpkg, listed, extras):
    """Optional imports (imported_modules) must come from install_deps.sh or install_extras.sh."""
    allowed = dpkg.closure(listed + extras) | dpkg.closure(dpkg.always)
    lines = [f"{owners[0]} is used (e.g. {path}: {usage.optional[path]}) but neither "
             f"scripts/install_deps.sh nor scripts/install_extras.sh installs it"
             for path, owners in sorted(dpkg.owners(list(usage.optional)).items())
             if owners and not allowed.intersection(owners)]
    for line in lines:
        report(line)
    if not lines and usage.optional:
        report(f"{len(usage.optional)} optional modules, each from scripts/install_deps.sh or "
               f"scripts/install_extras.sh")
    return not lines


def check_package_xml(repo, dpkg, listed):
    """Fails for a listed library whose rosdep key (ROSDEP_KEYS) package.xml lacks; warns about
    package.xml keys that relate to nothing install_deps.sh installs."""
    root = ElementTree.parse(os.path.join(repo, "package.xml")).getroot()
    keys = {element.text.strip() for tag in PACKAGE_XML_DEPENDS for element in root.iter(tag)}
    lines = [f"package.xml lacks <depend>{rosdep[0]}</depend> for {package}, which "
             f"scripts/install_deps.sh installs" for package, rosdep in sorted(ROSDEP_KEYS.items())
             if package in listed and not keys.intersection(rosdep)]
    for line in lines:
        report(line)
    closure = dpkg.closure(listed)
    related = {key for package, rosdep in ROSDEP_KEYS.items() if package in closure
               for key in rosdep}
    manifest_owners = dpkg.owners([f"/usr/share/{key}/package.xml" for key in keys])  # ROS packages
    related |= {key for key in keys
                if closure.intersection(manifest_owners[f"/usr/share/{key}/package.xml"])}
    if keys - related:
        report(f"warning: package.xml keys related to no package of scripts/install_deps.sh: "
               f"{', '.join(sorted(keys - related))}")
    return not lines


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    this_repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--repo", default=this_repo, help="the repository (default: this script's)")
    parser.add_argument("--build", help="the build folder (default: REPO/_build)")
    parser.add_argument("--without", action="append", default=[], metavar="PKG",
                        help="check as if scripts/install_deps.sh did not list PKG (repeatable)")
    parser.add_argument("--self-test", action="store_true",
                        help="also show that removing libnlopt-dev and other entries is caught")
    args = parser.parse_args()
    args.repo = os.path.abspath(args.repo)
    args.build = os.path.abspath(args.build or os.path.join(args.repo, "_build"))
    if not os.path.isfile(os.path.join(args.build, "CMakeCache.txt")):
        parser.error(f"no CMakeCache.txt in {args.build}: build first (scripts/build.sh)")
    return args


def main():
    if os.path.realpath(sys.executable) != os.path.realpath(DEBIAN_PYTHON):
        os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON, *sys.argv])  # modules must resolve as Debian's do
    sys.path.pop(0)  # this script's folder: the project's modules are not Debian's
    args = parse_arguments()
    start = time.monotonic()
    listed = install_deps_packages(args.repo)
    unknown = sorted(set(args.without) - set(listed))
    if unknown:
        sys.exit(f"check_deps: --without {', '.join(unknown)}: "
                 "scripts/install_deps.sh does not list it")
    listed = [package for package in listed if package not in args.without]
    dpkg = Dpkg()
    usage = collect_usage(args.repo, args.build)
    used = UsedPackages(usage, dpkg)
    passed = run_check(used, dpkg, listed)
    passed = check_optional(usage, dpkg, listed,
                            install_script_packages(args.repo, "install_extras.sh")) and passed
    passed = check_package_xml(args.repo, dpkg, listed) and passed
    if args.self_test:
        passed = run_self_test(used, dpkg, listed) and passed
    report(f"{'passed' if passed else 'FAILED'} in {time.monotonic() - start:.1f} s")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
