"""Helpers that declare whatever parameter they are asked about."""

from rcl_interfaces.msg import ParameterDescriptor


def declared(node, name, default, description=""):
    """Declare ``name`` on ``node`` with ``default`` and a description; give its value."""
    descriptor = ParameterDescriptor(description=description)
    node.declare_parameter(name, default, descriptor)
    return node.get_parameter(name).value
