"""Byte links to a drive: TCP, UDP (a line a datagram, Elmo's Ethernet port) and a serial port
(pyserial: an RS-232 adapter, or the pty of `uprog sim --pty`). Each sends bytes and receives
what came within a timeout; a link that went away raises ConnectionLost."""

import socket
import time
import urllib.parse

from .errors import ConnectionLost, UprogError


class TcpLink:
    datagrams = False

    def __init__(self, host, port, timeout_s):
        try:
            self._sock = socket.create_connection((host, port), timeout=timeout_s)
        except OSError as e:
            raise ConnectionLost(f"cannot reach tcp://{host}:{port}: {e}") from e

    def send(self, data):
        try:
            self._sock.sendall(data)
        except OSError as e:
            raise ConnectionLost(f"the drive closed the connection: {e}") from e

    def receive(self, timeout_s):
        """What arrived within timeout_s (b"" for none); ConnectionLost at the end of stream."""
        self._sock.settimeout(max(timeout_s, 0.001))
        try:
            data = self._sock.recv(65536)
        except socket.timeout:
            return b""
        except OSError as e:
            raise ConnectionLost(f"the drive closed the connection: {e}") from e
        if not data:
            raise ConnectionLost("the drive closed the connection")
        return data

    def close(self):
        self._sock.close()


class UdpLink(TcpLink):
    """One datagram a line, one reply datagram (docs/protocol.md, "UDP")."""

    datagrams = True

    def __init__(self, host, port, timeout_s):  # pylint: disable=super-init-not-called
        try:
            family = socket.getaddrinfo(host, port, type=socket.SOCK_DGRAM)[0]
            self._sock = socket.socket(family[0], socket.SOCK_DGRAM)
            self._sock.connect(family[4])
        except OSError as e:
            raise ConnectionLost(f"cannot reach udp://{host}:{port}: {e}") from e

    def send(self, data):
        try:
            self._sock.send(data)
        except OSError as e:
            raise ConnectionLost(f"the drive is not there: {e}") from e

    def receive(self, timeout_s):
        self._sock.settimeout(max(timeout_s, 0.001))
        try:
            return self._sock.recv(65536)
        except socket.timeout:
            return b""
        except OSError as e:  # ICMP port unreachable: nothing listens there
            raise ConnectionLost(f"the drive is not there: {e}") from e


class SerialLink:
    datagrams = False

    def __init__(self, path, baud):
        try:
            import serial  # pyserial, Debian's python3-serial
        except ImportError as e:
            raise UprogError("serial:// needs pyserial (Debian: python3-serial)") from e
        try:
            self._port = serial.Serial(path, baudrate=baud, timeout=0)
        except (serial.SerialException, OSError) as e:
            raise ConnectionLost(f"cannot open {path}: {e}") from e
        self._serial = serial

    def send(self, data):
        try:
            self._port.write(data)
            self._port.flush()
        except (self._serial.SerialException, OSError) as e:
            raise ConnectionLost(f"the serial port went away: {e}") from e

    def receive(self, timeout_s):
        deadline = time.monotonic() + timeout_s
        try:
            while True:
                waiting = self._port.in_waiting
                if waiting:
                    return self._port.read(waiting)
                if time.monotonic() >= deadline:
                    return b""
                time.sleep(0.002)
        except (self._serial.SerialException, OSError) as e:
            raise ConnectionLost(f"the serial port went away: {e}") from e

    def close(self):
        self._port.close()


def open_link(url, timeout_s):
    """tcp://HOST:PORT, udp://HOST:PORT, serial:///dev/ttyUSB0?baud=115200, or HOST:PORT (TCP)."""
    if "://" not in url:
        url = "tcp://" + url
    parts = urllib.parse.urlsplit(url)
    if parts.scheme in ("tcp", "udp"):
        if parts.hostname is None or parts.port is None:
            raise UprogError(f"{url}: give {parts.scheme}://HOST:PORT")
        link = TcpLink if parts.scheme == "tcp" else UdpLink
        return link(parts.hostname, parts.port, timeout_s)
    if parts.scheme == "serial":
        query = urllib.parse.parse_qs(parts.query)
        baud = int(query.get("baud", ["115200"])[0])
        return SerialLink(parts.path, baud)
    raise UprogError(f"{url}: the scheme is tcp://, udp:// or serial://")
