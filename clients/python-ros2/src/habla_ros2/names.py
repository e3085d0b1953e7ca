"""How HABLA's names become ROS 2 names.

A ROS 2 name token holds letters, digits and underscores, does not start with a digit, has no two underscores
in a row and does not end with one. So a system or socket name is made valid by: every character other than
a letter, digit or underscore becomes an underscore; runs of underscores become one; underscores at both
ends go; a name that then starts with a digit gets an "n" before it; an empty name becomes "unnamed".

    pioneer-2dx -> pioneer_2dx      distance_angle -> distance_angle      2d.lidar -> n2d_lidar
"""

import re

ROOT = "/habla"
RESERVED = ("set", "state", "sample")   # suffixes the face uses under a socket's topic


def token(name):
    """A HABLA name as one valid ROS 2 name token."""
    t = re.sub(r"[^A-Za-z0-9_]", "_", name or "")
    t = re.sub(r"_+", "_", t).strip("_")
    if not t:
        return "unnamed"
    return "n" + t if t[0].isdigit() else t


def socket_topic(system, socket):
    """The topic of a socket's (first) output: /habla/<system>/<socket>."""
    return "%s/%s/%s" % (ROOT, token(system), token(socket))


def main_output(socket, outputs):
    """The output that takes the socket's own topic: the one named like the socket, else the first."""
    named = [o for o in outputs if o == socket]
    return named[0] if named else (outputs[0] if outputs else None)


def output_topic(system, socket, output, main):
    """The topic of one output: the socket's own topic for its main output, /habla/<system>/<socket>/<output>
    for the others (an output named like one of the face's suffixes gets "_out" after it)."""
    base = socket_topic(system, socket)
    if main:
        return base
    t = token(output)
    return "%s/%s" % (base, t + "_out" if t in RESERVED else t)


def set_topic(system, socket, input_name, first):
    """Where actions for a socket's control input come from: /habla/<system>/<socket>/set (its first input),
    /habla/<system>/<socket>/set/<input> for the others."""
    base = socket_topic(system, socket) + "/set"
    return base if first else "%s/%s" % (base, token(input_name))
