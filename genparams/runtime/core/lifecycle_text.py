"""The words of ``configure_only``: one source for descriptors, docs and refusals."""

CONFIGURE_ONLY_TEXT = "changes only while the lifecycle node is unconfigured or inactive"
