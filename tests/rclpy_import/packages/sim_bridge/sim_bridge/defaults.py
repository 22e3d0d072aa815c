RATE_HZ = 30.0
TOPICS = ["/clock", "/tf"]
