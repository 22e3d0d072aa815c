"""Import of generate_parameter_library (GPL) parameter files into genparams schemas."""
