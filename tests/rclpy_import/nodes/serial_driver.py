"""A driver whose parameters are declared by a function of the module, not by a class."""

import rclpy
from rclpy.node import Node


def declare(driver: Node) -> tuple[str, int]:
    serial_port = driver.declare_parameter("port", "/dev/ttyUSB0").value
    serial_baud = driver.declare_parameter("baud", 4800).value
    return serial_port, serial_baud


def main() -> None:
    rclpy.init()
    driver = Node("nmea_serial_driver")
    declare(driver)
    driver.destroy_node()
    rclpy.shutdown()
