# world/: the 2D multi-party world on Box2D, and world_node.
