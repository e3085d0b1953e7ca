"""habla-ros2: HABLA in a ROS 2 graph (docs/ros2.md).

    habla-ros2 face CONFIG          the daemon's sockets as ROS 2 topics
    habla-ros2 body [options]       a ROS 2 base (REP-105 topics) as a HABLA body, by the interface protocol
    habla-ros2 sim-base [options]   a simulated ROS 2 base in a simulated world, with the teacher
"""

import argparse
import sys

from . import body, face, sim_base


def main(argv=None):
    p = argparse.ArgumentParser(prog="habla-ros2", description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    face.add_arguments(sub.add_parser("face", help="the daemon's sockets as ROS 2 topics"))
    body.add_arguments(sub.add_parser("body", help="a ROS 2 base as a HABLA body"))
    sim_base.add_arguments(sub.add_parser("sim-base", help="a simulated ROS 2 base with the teacher"))
    args = p.parse_args(sys.argv[1:] if argv is None else argv)
    if args.command == "face":
        return face.run(args)
    if args.command == "body":
        return body.run(args)
    return sim_base.run(args)


if __name__ == "__main__":
    sys.exit(main())
