"""Parallel gripper driver."""
