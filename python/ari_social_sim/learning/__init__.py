"""Learning environments over ari_social_sim's in-process engine (docs/learning.md).

    from ari_social_sim import learning
    env = learning.make("join_group", walkers=4)
    obs, info = env.reset(seed=1)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

    envs = learning.make_vector("join_group", num_envs=16, threads=2)

Tasks: go_to_pose, approach_person, join_group, join_conversation (join_group's episodes with a
talking group; the action gains `speak`), scenario:<file> (a scenario file, or the name of
a shipped one, e.g. scenario:join_group, with the policy driving ARI's goals), and dialogue
(DialogueEnv). Options are the fields of the task file
(config/learning/<task>.yaml), given as keyword arguments: a nested section as a dict
(rewards={"arrival": 20}). `config=` names another task file to start from.

The environments follow Gymnasium's conventions without needing the gymnasium package; when it is
importable, NavigationEnv subclasses gymnasium.Env, its spaces are gymnasium Boxes, and the tasks
are registered as "ari_social_sim/<task>-v0".
"""

import json
import os

import numpy as np

from ari_social_sim import _learning

try:  # optional: only used to be a gymnasium.Env when gymnasium is there
    import gymnasium as _gymnasium
except ImportError:  # pragma: no cover - Debian has no gymnasium
    _gymnasium = None

if _gymnasium is not None:
    from gymnasium.spaces import Box
    _EnvBase = _gymnasium.Env
else:
    from ari_social_sim.learning.spaces import Box
    _EnvBase = object

TASKS = ("go_to_pose", "approach_person", "join_group", "join_conversation")
DIALOGUE_TASK = "dialogue"
ACTION_NAMES = tuple(_learning.action_names)
SEED_LIMIT = 2 ** 64  # seeds are unsigned 64-bit integers
MAX_ENVS = _learning.max_envs        # a vector environment's size, at most
MAX_THREADS = _learning.max_threads  # and its threads


def _check_seed(seed):
    """None, or an integer in [0, 2^64); anything else raises ValueError naming `seed`."""
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer))
                             or not 0 <= int(seed) < SEED_LIMIT):
        raise ValueError(f"seed: expected an integer in [0, 2^64) or None, got {seed!r}")
    return None if seed is None else int(seed)


def package_dir():
    """The ari_social_sim package directory (config/, worlds/), found as rospack finds it."""
    override = os.environ.get("ARI_SOCIAL_SIM_DIR")
    if override:
        return override
    import rospkg
    return rospkg.RosPack().get_path("ari_social_sim")


SCENARIO_PREFIX = "scenario:"


def _scenario_file(name, root):
    """A scenario file as given, else the package's scenarios/<name>.yaml."""
    if os.path.isfile(name):
        return os.path.abspath(name)
    shipped = os.path.join(root, "scenarios", name + ("" if name.endswith(".yaml") else ".yaml"))
    if os.path.isfile(shipped):
        return shipped
    raise ValueError(f"task: no scenario file {name!r} (nor {shipped})")


def _setup(task, options):
    is_scenario = isinstance(task, str) and task.startswith(SCENARIO_PREFIX)
    if not isinstance(task, str) or (task not in TASKS and not is_scenario):
        raise ValueError(f"task: expected one of {', '.join(TASKS)} or scenario:<file>, "
                         f"got {task!r}")
    options = dict(options)
    root = package_dir()
    kind = "scenario" if is_scenario else task
    task_file = options.pop("config", None) or os.path.join(root, "config", "learning",
                                                            kind + ".yaml")
    for reserved in ("task", "scenario"):
        if reserved in options:
            raise ValueError(f"{reserved}: give it as make()'s first argument, not as an option")
    options["task"] = kind
    if is_scenario:
        options["scenario"] = _scenario_file(task[len(SCENARIO_PREFIX):], root)
    try:
        text = json.dumps(options)
    except TypeError as error:
        raise ValueError(f"make() options: {error}") from None
    return _learning.NavEnvSetup.load(root, task_file, text, "make() options")


_FLOAT32_MAX = float(np.finfo(np.float32).max)


def _numbers(name, values):
    """`values` as a float32 array; ValueError naming `name` when they are not numbers. A finite
    number beyond float32's range (1e300) is clipped to it, not turned into inf: actions are
    clipped to ARI's limits, and only NaN and infinities are refused (by the core, naming the
    field)."""
    try:
        array = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected numbers, got {values!r}") from None
    clipped = np.where(np.isfinite(array), np.clip(array, -_FLOAT32_MAX, _FLOAT32_MAX), array)
    return clipped.astype(np.float32)


def _observation_space(core):
    low = np.empty(core.observation_size, np.float32)
    high = np.empty(core.observation_size, np.float32)
    layout = {}
    for name, offset, size, field_low, field_high in core.observation_fields():
        low[offset:offset + size] = field_low
        high[offset:offset + size] = field_high
        layout[name] = slice(offset, offset + size)
    return Box(low, high, dtype=np.float32), layout


def _action_space(setup):
    """[linear, angular, pan] within ARI's limits; join_conversation adds speak in [0, 1]."""
    low, high = _learning.action_bounds()
    if setup.action_size > len(low):
        low, high = low + [0.0], high + [1.0]
    return Box(np.array(low, np.float32), np.array(high, np.float32), dtype=np.float32)


class _Closable:
    """close() for the environments: after it, every method raises ValueError "closed
    environment" (not an AttributeError from a released core); closing twice is harmless."""

    _core = None

    def close(self):
        self._core = None

    def _open_core(self):
        if self._core is None:
            raise ValueError(f"closed environment: {type(self).__name__}.close() was called; "
                             f"make a new environment")
        return self._core


class NavigationEnv(_Closable, _EnvBase):
    """One navigation environment (docs/learning.md): observations from perception, actions
    (linear m/s, angular rad/s, head pan rad, and speak in [0, 1] for join_conversation) clipped
    to ARI's limits, rewards and metrics on the truth. Not thread-safe; use make_vector for several."""

    metadata = {"render_modes": []}

    def __init__(self, task="join_group", **options):
        self._setup = _setup(task, options)
        self._core = _learning.NavEnv(self._setup)
        self.observation_space, self.observation_layout = _observation_space(self._core)
        self.action_space = _action_space(self._setup)
        self.task = task
        self.time_limit_s = self._setup.time_limit_s
        self.step_s = self._setup.step_s
        self.arrival = self._setup.arrival  # (position m, heading rad) tolerances
        self.observation_config = self._setup.observation_config

    def reset(self, seed=None, options=None):
        """Starts an episode: that of `seed`, or the next in this environment's sequence.
        `options` may hold {"seed": int} only (as gymnasium allows); anything else is refused."""
        core = self._open_core()
        if options is not None:
            if not isinstance(options, dict):
                raise ValueError(f"options: expected a dict or None, got {type(options).__name__}")
            unknown = sorted(set(options) - {"seed"})
            if unknown:
                raise ValueError(f"options: unknown key {unknown[0]!r}; expected only 'seed'")
            if seed is None:
                seed = options.get("seed")
        observation = core.reset(_check_seed(seed))
        return observation, core.metrics()

    def step(self, action):
        core = self._open_core()
        observation, reward, terminated, truncated = core.step(_numbers("action", action))
        return observation, reward, terminated, truncated, core.metrics()


class VectorNavigationEnv(_Closable):
    """num_envs navigation environments stepped in one call, optionally on several threads.
    Environment i plays seeds seed+i, seed+i+num_envs, ...; an ended episode is reset in the same
    step, its last observation in infos["final_observation"][i] (zeros for the others) and its
    metrics in infos["final_info"][i] (None for environments that did not end)."""

    def __init__(self, task="join_group", num_envs=8, threads=1, **options):
        for name, value, limit in (("num_envs", num_envs, MAX_ENVS), ("threads", threads, MAX_THREADS)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) \
                    or not 1 <= value <= limit:
                raise ValueError(f"{name}: expected an integer in [1, {limit}], got {value!r}")
        self._setup = _setup(task, options)
        self._core = _learning.VectorNavEnv(self._setup, int(num_envs), int(threads))
        self.num_envs = int(num_envs)
        self.single_observation_space, self.observation_layout = _observation_space(self._core)
        self.single_action_space = _action_space(self._setup)
        self.observation_space = Box(
            np.tile(self.single_observation_space.low, (self.num_envs, 1)),
            np.tile(self.single_observation_space.high, (self.num_envs, 1)), dtype=np.float32)
        self.action_space = Box(np.tile(self.single_action_space.low, (self.num_envs, 1)),
                                np.tile(self.single_action_space.high, (self.num_envs, 1)),
                                dtype=np.float32)
        self.task = task

    def reset(self, seed=None, options=None):
        if options is not None:
            raise ValueError("options: a vector environment takes none")
        observations = self._open_core().reset(_check_seed(seed))
        return observations, {}

    def step(self, actions):
        core = self._open_core()
        observations, rewards, terminated, truncated, finals = core.step(
            _numbers("actions", actions))
        ended = terminated | truncated
        infos = {"_final": ended}
        if ended.any():
            infos["final_observation"] = finals
            infos["final_info"] = [core.final_metrics(i) if ended[i] else None
                                   for i in range(self.num_envs)]
        return observations, rewards, terminated, truncated, infos


class DialogueEnv(_Closable):
    """dialogue_node's rl_env mode (docs/dialogue.md) in-process: the simulated patient and
    companion answer ARI's dialogue acts. Observations and infos are dicts with the fields of
    /sim/dialogue/step's response; an action is a dict {"acts": [...], "addressees": [...],
    "text": ""} (a plain list is the acts), checked as the service checks it. The observations and
    actions are text, so observation_space and action_space are None."""

    observation_space = None
    action_space = None

    def __init__(self, settings=None):
        if settings is None:
            settings = os.path.join(package_dir(), "config", "dialogue", "simulation.yaml")
        self._core = _learning.DialogueEnv(settings)
        self.roles = list(self._core.roles)
        self._next_seed = 0

    def reset(self, seed=None, options=None):
        if options is not None:
            raise ValueError("options: the dialogue environment takes none")
        core = self._open_core()
        seed = _check_seed(seed)
        seed = self._next_seed if seed is None else seed
        self._next_seed = (seed + 1) % SEED_LIMIT
        return core.reset(seed)

    def step(self, action):
        core = self._open_core()
        if isinstance(action, dict):
            unknown = sorted(set(action) - {"acts", "addressees", "text"})
            if unknown:
                raise ValueError(f"action: unknown key {unknown[0]!r}; expected acts, addressees, "
                                 f"text")
            acts = action.get("acts", [])
            addressees = action.get("addressees", [])
            text = action.get("text", "")
        elif isinstance(action, (list, tuple)):
            acts, addressees, text = action, [], ""
        else:
            raise ValueError(f"action: expected a dict or a list of acts, got "
                             f"{type(action).__name__}")
        for name, values in (("acts", acts), ("addressees", addressees)):
            if not isinstance(values, (list, tuple)) or not all(isinstance(v, str) for v in values):
                raise ValueError(f"action.{name}: expected a list of strings, got {values!r}")
        if not isinstance(text, str):
            raise ValueError(f"action.text: expected a string, got {text!r}")
        return core.step(list(acts), list(addressees), text)


def load_policy(path):
    """A trained policy file (docs/learning.md, section 10) as social_mpc_node runs it: `act(obs)`
    gives the command [linear, angular, pan] for an observation, by the same C++ code."""
    return _learning.MlpPolicy(str(path))


def make(task, **options):
    """One environment of `task`: go_to_pose, approach_person, join_group (NavigationEnv), or
    dialogue (DialogueEnv; option settings= names another dialogue settings file)."""
    if task == DIALOGUE_TASK:
        return DialogueEnv(**options)
    return NavigationEnv(task, **options)


def make_vector(task, num_envs, threads=1, **options):
    """num_envs environments of `task` stepped together on `threads` threads."""
    return VectorNavigationEnv(task, num_envs=num_envs, threads=threads, **options)


if _gymnasium is not None:  # pragma: no cover - Debian has no gymnasium
    for _task in TASKS:
        _gymnasium.register(id=f"ari_social_sim/{_task}-v0",
                            entry_point=NavigationEnv, kwargs={"task": _task})
