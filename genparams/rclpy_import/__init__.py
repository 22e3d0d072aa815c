"""Import of hand-written rclpy nodes (their declare_parameter calls) into genparams schemas."""
