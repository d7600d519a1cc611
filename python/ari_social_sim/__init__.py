"""ari_social_sim: the simulator's Python package (messages, and the learning environments)."""
