"""Reading ROS 2 params files exactly as rcl does, and checking them against a schema."""
