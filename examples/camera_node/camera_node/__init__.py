"""Example package: a camera driver node configured by genparams."""
