"""Tests of the Python learning module (ari_social_sim.learning), run by the README's test command
through catkin's run_tests (pytest)."""

import math

import numpy as np
import pytest

from ari_social_sim import learning


def test_spaces_match_the_observations_and_the_layout_covers_them():
    env = learning.make("join_group", walkers=2)
    obs, info = env.reset(seed=3)
    assert obs.shape == env.observation_space.shape
    assert obs.dtype == np.float32
    assert env.observation_space.contains(obs)
    sizes = {name: s.stop - s.start for name, s in env.observation_layout.items()}
    assert sizes["robot"] == 3 and sizes["goal"] == 6 and sizes["group"] == 4
    assert sizes["people"] == 6 * 9 and sizes["occupancy"] == 16 * 16
    assert sum(sizes.values()) == obs.shape[0]
    assert env.action_space.shape == (3,)
    np.testing.assert_allclose(env.action_space.low, [-0.2, -2.094, -1.309], atol=1e-6)
    np.testing.assert_allclose(env.action_space.high, [1.0, 2.094, 1.309], atol=1e-6)
    for _ in range(50):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        assert env.observation_space.contains(obs)
        assert isinstance(reward, float) and math.isfinite(reward)
        occupancy = obs[env.observation_layout["occupancy"]]
        assert set(np.unique(occupancy)) <= {0.0, 1.0}
        if terminated or truncated:
            break


def test_actions_outside_the_limits_are_clipped():
    env = learning.make("go_to_pose", terminate_on_collision=False)
    env.reset(seed=5)
    for _ in range(60):
        obs, *_ = env.step([9.0, 0.0, -5.0])
    robot = obs[env.observation_layout["robot"]]
    assert 0.9 < robot[0] <= 1.0 + 1e-6  # linear velocity at ARI's 1 m/s
    assert robot[2] == pytest.approx(-1.309, abs=0.01)  # head pan at its limit
    # Finite however large: clipped too, not refused as the inf float32 would make of it.
    for _ in range(60):
        obs, *_ = env.step([1e300, 0.0, 1e300])
    robot = obs[env.observation_layout["robot"]]
    assert 0.9 < robot[0] <= 1.0 + 1e-6
    assert robot[2] == pytest.approx(1.309, abs=0.01)
    envs = learning.make_vector("go_to_pose", 2, terminate_on_collision=False)
    envs.reset(seed=5)
    envs.step(np.full((2, 3), -1e300))


@pytest.mark.parametrize("action, message", [
    ([0.1, 0.2], "action: expected shape (3,), got (2,)"),
    ([[0.1, 0.2, 0.3]], "action: expected shape (3,), got (1, 3)"),
    ([0.1, float("nan"), 0.0], "action[1] (angular): expected a finite number"),
    ([float("inf"), 0.0, 0.0], "action[0] (linear): expected a finite number"),
    ([0.0, 0.0, float("nan")], "action[2] (pan): expected a finite number, got nan"),
    (["fast", "left", "up"], "action: expected numbers, got ['fast', 'left', 'up']"),
])
def test_wrong_shapes_and_non_finite_actions_are_refused_by_name(action, message):
    env = learning.make("join_group")
    env.reset(seed=1)
    with pytest.raises(ValueError) as error:
        env.step(action)
    assert message in str(error.value)


CONVERSATION_INFO = ("turn_transitions", "overlap_share", "listener_gaze_at_speaker",
                     "ari_floor_share", "ari_interruptions", "ari_addressed_after_s",
                     "ari_entered_in_pause", "interruptions", "intrusions", "entries", "answers", "answer_delay_s")


def test_join_conversation_takes_speak_and_reports_the_conversation():
    env = learning.make("join_conversation", time_limit=3.0)
    assert env.action_space.shape == (4,)
    assert env.action_space.low[3] == 0.0 and env.action_space.high[3] == 1.0
    obs, info = env.reset(seed=1)
    assert obs.shape == env.observation_space.shape
    assert env.observation_layout["conversation"].stop == obs.shape[0]
    for key in CONVERSATION_INFO:
        assert np.isfinite(info[key]), key
    with pytest.raises(ValueError, match=r"action: expected shape \(4,\), got \(3,\)"):
        env.step([0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"action\[3\] \(speak\): expected a finite number"):
        env.step([0.0, 0.0, 0.0, float("nan")])
    for _ in range(20):
        obs, reward, terminated, truncated, info = env.step([0.0, 0.0, 0.0, 1.0])
    assert info["ari_lines"] >= 1  # ARI's greeting
    assert np.isfinite(reward)
    envs = learning.make_vector("join_conversation", 2, time_limit=3.0)
    envs.reset(seed=1)
    with pytest.raises(ValueError, match=r"actions: expected shape \(2, 4\), got \(2, 3\)"):
        envs.step(np.zeros((2, 3)))
    envs.step(np.zeros((2, 4)))


def test_vector_actions_are_checked_before_any_environment_steps():
    envs = learning.make_vector("join_group", 3)
    envs.reset(seed=1)
    with pytest.raises(ValueError, match=r"actions: expected shape \(3, 3\), got \(2, 3\)"):
        envs.step(np.zeros((2, 3)))
    bad = np.zeros((3, 3), np.float32)
    bad[2, 2] = np.nan
    with pytest.raises(ValueError, match=r"actions\[2, 2\] \(pan\)"):
        envs.step(bad)


def test_reset_options_and_make_options_are_validated():
    env = learning.make("join_group")
    with pytest.raises(ValueError, match="options: unknown key 'difficulty'"):
        env.reset(options={"difficulty": 3})
    with pytest.raises(ValueError, match="seed: expected an integer"):
        env.reset(seed=1.5)
    with pytest.raises(ValueError, match="seed: expected an integer"):
        env.reset(seed=-1)
    with pytest.raises(ValueError, match=r"seed: expected an integer in \[0, 2\^64\)"):
        env.reset(seed=2 ** 64)
    env.reset(seed=2 ** 64 - 1)  # the largest seed plays
    obs_a, _ = env.reset(options={"seed": 7})
    obs_b, _ = env.reset(seed=7)
    np.testing.assert_array_equal(obs_a, obs_b)
    with pytest.raises(ValueError, match="task: expected one of"):
        learning.make("dance")
    with pytest.raises(ValueError, match="walkers"):
        learning.make("join_group", walkers=-3)
    with pytest.raises(ValueError, match="arival"):
        learning.make("join_group", rewards={"arival": 1})
    with pytest.raises(ValueError, match="num_envs"):
        learning.make_vector("join_group", 0)
    with pytest.raises(ValueError, match=r"num_envs: expected an integer in \[1, 4096\]"):
        learning.make_vector("join_group", 10 ** 7)
    with pytest.raises(ValueError, match="threads"):
        learning.make_vector("join_group", 2, threads=0)
    with pytest.raises(ValueError, match=r"threads: expected an integer in \[1, 64\]"):
        learning.make_vector("join_group", 2, threads=10 ** 6)
    with pytest.raises(ValueError, match="nonexistent.yaml: cannot open the file"):
        learning.make("join_group", config="/nonexistent.yaml")
    with pytest.raises(ValueError, match="cannot open the file"):
        learning.load_policy("/nonexistent/policy.yaml")


def _rollout(env, seed, steps):
    obs, info = env.reset(seed=seed)
    trace = [obs.copy()]
    for t in range(steps):
        action = [0.4 + 0.3 * math.sin(0.1 * t), 0.8 * math.cos(0.07 * t), 0.3]
        obs, reward, terminated, truncated, info = env.step(action)
        trace += [obs.copy(), np.array([reward, terminated, truncated]), info]
        if terminated or truncated:
            break
    return trace


def test_the_same_seed_gives_the_same_observations_rewards_and_infos():
    a = _rollout(learning.make("join_group", walkers=3), 11, 200)
    b = _rollout(learning.make("join_group", walkers=3), 11, 200)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        if isinstance(x, dict):
            assert x == y
        else:
            assert x.tobytes() == y.tobytes()


def test_vector_results_do_not_depend_on_the_thread_count():
    runs = []
    for threads in (1, 2):
        envs = learning.make_vector("join_group", 4, threads=threads, time_limit=2.0)
        obs, _ = envs.reset(seed=20)
        trace = [obs]
        for t in range(60):
            actions = np.tile([0.5, 0.3 * math.sin(t * 0.1), 0.0], (4, 1))
            obs, rewards, terminated, truncated, infos = envs.step(actions)
            trace += [obs, rewards, terminated, truncated]
            if "final_info" in infos:
                trace.append(np.array([i["time_s"] if i else -1 for i in infos["final_info"]]))
        runs.append(trace)
    for x, y in zip(*runs):
        assert x.tobytes() == y.tobytes()


def test_episodes_end_as_documented():
    # Truncated at the time limit: 1 s is 20 steps of 0.05 s.
    env = learning.make("join_group", time_limit=1.0)
    env.reset(seed=2)
    for step in range(1, 100):
        _, _, terminated, truncated, info = env.step([0.0, 0.0, 0.0])
        if terminated or truncated:
            break
    assert (step, terminated, truncated) == (20, False, True)
    assert info["time_s"] == pytest.approx(1.0)
    with pytest.raises(ValueError, match="after the episode ended"):
        env.step([0.0, 0.0, 0.0])
    # A vector environment resets an ended episode in the same step and reports its end.
    envs = learning.make_vector("join_group", 2, time_limit=1.0)
    envs.reset(seed=2)
    for step in range(1, 100):
        _, _, terminated, truncated, infos = envs.step(np.zeros((2, 3)))
        if truncated.any():
            break
    assert step == 20 and truncated.all() and infos["_final"].all()
    assert infos["final_info"][0]["time_s"] == pytest.approx(1.0)
    assert infos["final_observation"].shape == (2, envs.single_observation_space.shape[0])


def test_the_dialogue_environment_plays_dialogue_nodes_rl_env():
    env = learning.make("dialogue")
    assert env.roles == ["patient", "companion"]
    first, info = env.reset(seed=4)
    again, info_again = env.reset(seed=4)
    assert first == again and info == info_again
    assert set(info["patience"]) == {"patient", "companion"}
    observation, reward, terminated, truncated, info = env.step(
        {"acts": ["greet()"], "addressees": ["patient"]})
    assert observation["robot_turn"] == 1 and isinstance(reward, float)
    for heard in observation["heard"]:
        assert set(heard) == {"dropped", "speaker", "addressees", "text", "acts", "confidence",
                              "word_errors"}
    with pytest.raises(ValueError, match=r"addressees\[0\]: expected one of the humans' roles"):
        env.step({"acts": ["greet()"], "addressees": ["doctor"]})
    with pytest.raises(ValueError, match=r"acts\[0\]"):
        env.step(["greet("])
    with pytest.raises(ValueError, match="action: unknown key 'act'"):
        env.step({"act": ["greet()"]})
    steps = 1
    while not (terminated or truncated):
        observation, reward, terminated, truncated, info = env.step(["bye()"])
        steps += 1
    assert steps < 200
    with pytest.raises(ValueError, match="the episode is over"):
        env.step([])


def test_a_scenario_is_played_with_the_policy_driving_aris_goals():
    env = learning.make("scenario:join_group", perception_errors=False)
    obs, info = env.reset(seed=1)
    layout = env.observation_layout
    # The first observation comes when navigation first asks: the goal of the script's join.
    assert obs[layout["goal"]][0] == 1.0 and obs[layout["group"]][0] == 1.0
    total, steps = 0.0, 0
    while True:
        goal = obs[layout["goal"]]
        x, y, distance = goal[1], goal[2], goal[5]
        bearing = math.atan2(y, x)
        turn = math.atan2(goal[4], goal[3]) if distance < 0.1 else bearing
        linear = 0.0 if distance < 0.1 or abs(bearing) > 0.5 else min(0.5, distance)
        obs, reward, terminated, truncated, info = env.step([linear, 2.0 * turn, 0.0])
        total += reward
        steps += 1
        if terminated or truncated:
            break
    # A go-to-the-goal controller joins the group; the script then greets and ends with success.
    assert terminated and info["success"], info
    assert info["path_length_m"] > 1.0 and steps > 20
    again = learning.make("scenario:join_group", perception_errors=False)
    np.testing.assert_array_equal(again.reset(seed=1)[0], env.reset(seed=1)[0])
    with pytest.raises(ValueError, match="no scenario file"):
        learning.make("scenario:no_such_scenario")


def test_scenario_vector_environments_do_not_depend_on_the_thread_count():
    runs = []
    for threads in (1, 2):
        envs = learning.make_vector("scenario:join_group", 2, threads=threads)
        obs, _ = envs.reset(seed=3)
        trace = [obs]
        for t in range(30):
            obs, rewards, terminated, truncated, _ = envs.step(np.tile([0.3, 0.2, 0.0], (2, 1)))
            trace += [obs, rewards, terminated, truncated]
        runs.append(trace)
    for x, y in zip(*runs):
        assert x.tobytes() == y.tobytes()


def test_closed_environments_say_so_instead_of_an_attribute_error():
    for env, call in ((learning.make("join_group"), lambda e: e.step([0.0, 0.0, 0.0])),
                      (learning.make_vector("join_group", 2), lambda e: e.step(np.zeros((2, 3)))),
                      (learning.make("dialogue"), lambda e: e.step(["greet()"]))):
        env.reset(seed=1)
        env.close()
        env.close()  # twice is harmless
        for method in (call, lambda e: e.reset(seed=1)):
            with pytest.raises(ValueError, match=r"closed environment: \w+Env.close\(\) was called"):
                method(env)
