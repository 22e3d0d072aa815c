"""The pure part of the runtime: specs, types, validators, rules, the typed tree, names, codecs.

Nothing here imports rclpy or a ROS message package, so everything above it (the
compiler, check-params, tune) can use it without a ROS install.
"""
