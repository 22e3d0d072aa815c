"""genparams audit: check a running graph against the schemas its nodes publish."""
