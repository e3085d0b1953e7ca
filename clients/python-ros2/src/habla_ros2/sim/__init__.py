"""A simulated ROS 2 base in the simulator's worlds: the world, the body, the teacher and their servers."""
