"""Battery monitor."""
