"""Benchmarks of genparams against hand-written rclpy: ``make bench`` writes docs/benchmarks.md."""
