"""Constants the driver's defaults come from."""

DEFAULT_BAUD = 4800
TIMEOUT_S = 2.0


class Frames:
    FRAME = "gps"
    CHILD = FRAME + "_link"
