"""A generated class declared on an rclpy node: declaring, checking sets, committing, notifying."""
