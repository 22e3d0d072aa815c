"""Range filter for a lidar scan."""
