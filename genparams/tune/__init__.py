"""genparams tune: a web page to tune the parameters of a running ROS graph."""
