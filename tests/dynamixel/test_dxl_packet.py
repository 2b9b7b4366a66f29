"""Protocol 2.0 frames against the ROBOTIS e-manual's example packets and the SDK's own CRC."""

from __future__ import annotations

import random

import pytest

from armkit.devices import _dxl_packet as pkt

# (frame built by armkit, the e-manual's bytes)
MANUAL_INSTRUCTIONS = [
    (pkt.ping(1), "FF FF FD 00 01 03 00 01 19 4E"),
    (pkt.read(1, 132, 4), "FF FF FD 00 01 07 00 02 84 00 04 00 1D 15"),
    (
        pkt.write(1, 116, (512).to_bytes(4, "little")),
        "FF FF FD 00 01 09 00 03 74 00 00 02 00 00 CA 89",
    ),
    (pkt.sync_read(132, 4, [1, 2]), "FF FF FD 00 FE 09 00 82 84 00 04 00 01 02 CE FA"),
    (
        pkt.sync_write(116, 4, {1: (150).to_bytes(4, "little"), 2: (170).to_bytes(4, "little")}),
        "FF FF FD 00 FE 11 00 83 74 00 04 00 01 96 00 00 00 02 AA 00 00 00 82 87",
    ),
    (pkt.reboot(1), "FF FF FD 00 01 03 00 08 2F 4E"),
]
MANUAL_STATUSES = [
    # PING reply: model 1030, firmware 38
    (1, 0, bytes([0x06, 0x04, 0x26]), "FF FF FD 00 01 07 00 55 00 06 04 26 65 5D"),
    # READ / SYNC_READ replies: Present Position 166 and 2079
    (1, 0, bytes([0xA6, 0, 0, 0]), "FF FF FD 00 01 08 00 55 00 A6 00 00 00 8C C0"),
    (2, 0, bytes([0x1F, 0x08, 0, 0]), "FF FF FD 00 02 08 00 55 00 1F 08 00 00 BA BE"),
    # WRITE / REBOOT reply: no error, no data
    (1, 0, b"", "FF FF FD 00 01 04 00 55 00 A1 0C"),
]


@pytest.mark.parametrize(("built", "manual"), MANUAL_INSTRUCTIONS)
def test_instruction_frames_match_the_manual(built: bytes, manual: str) -> None:
    assert built == bytes.fromhex(manual)


@pytest.mark.parametrize(("sid", "error", "data", "manual"), MANUAL_STATUSES)
def test_status_frames_match_the_manual(sid: int, error: int, data: bytes, manual: str) -> None:
    frame = bytes.fromhex(manual)
    assert pkt.status(sid, error, data) == frame
    decoded = pkt.decode(frame)
    assert (decoded.id, decoded.instruction, decoded.error, decoded.data) == (
        sid,
        0x55,
        error,
        data,
    )


def test_crc_agrees_with_the_sdk_table_on_random_bytes() -> None:
    from dynamixel_sdk import PacketHandler

    sdk = PacketHandler(2.0)
    rng = random.Random(5)
    for _ in range(200):
        data = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64)))
        assert pkt.crc16(data) == sdk.updateCRC(0, list(data), len(data))


def test_stuffing_inserts_fd_after_ff_ff_fd_and_round_trips() -> None:
    frame = pkt.write(1, 116, bytes([0xFF, 0xFF, 0xFD, 0x00]))
    assert bytes.fromhex("03 74 00 FF FF FD FD 00") in frame
    assert int.from_bytes(frame[5:7], "little") == 1 + 2 + 5 + 2  # INST + addr + stuffed data + CRC
    assert pkt.decode(frame).params == bytes([116, 0, 0xFF, 0xFF, 0xFD, 0x00])


def test_stuffing_matches_the_sdk_packet_bytes() -> None:
    from dynamixel_sdk import PacketHandler

    sdk = PacketHandler(2.0)
    params = [0x74, 0x00, 0xFF, 0xFF, 0xFD, 0x01]
    tx = [0xFF, 0xFF, 0xFD, 0x00, 7, len(params) + 3, 0, 0x03, *params, 0, 0]
    stuffed = sdk.addStuffing(tx)
    length = stuffed[5] | stuffed[6] << 8
    body = bytes(stuffed[: 7 + length - 2])
    crc = sdk.updateCRC(0, list(body), len(body))
    assert pkt.write(7, 116, bytes(params[2:])) == body + bytes([crc & 0xFF, crc >> 8])


def test_random_payloads_round_trip_through_the_stream_splitter() -> None:
    rng = random.Random(11)
    for _ in range(100):
        params = bytes(rng.choice([0xFF, 0xFD, 0x00, rng.randrange(256)]) for _ in range(20))
        frame = pkt.encode(rng.randrange(253), pkt.Inst.WRITE, params)
        garbage = bytes([0xFF, 0x00, 0xFF, 0xFF])
        found, consumed = pkt.split_frame(garbage + frame + frame[:5])
        assert found == frame and consumed == len(garbage) + len(frame)
        assert pkt.decode(found).params == params


def test_split_frame_waits_for_a_whole_frame() -> None:
    frame = pkt.ping(3)
    assert pkt.split_frame(frame[:-1]) == (None, 0)
    assert pkt.split_frame(b"\x01\x02") == (None, 0)


@pytest.mark.parametrize(
    "mutate",
    [
        lambda f: f[:-1] + bytes([f[-1] ^ 1]),  # CRC
        lambda f: b"\xff\xff\xfe\x00" + f[4:],  # header
        lambda f: f[:5] + bytes([f[5] + 1]) + f[6:],  # length
    ],
)
def test_decode_rejects_damaged_frames(mutate: object) -> None:
    with pytest.raises(pkt.PacketError):
        pkt.decode(mutate(pkt.read(1, 132, 4)))  # type: ignore[operator]


def test_status_alert_bit_and_error_text() -> None:
    status = pkt.decode(pkt.status(12, 0x80 | 4))
    assert status.alert and status.error & 0x7F == 4
    assert pkt.describe_error(status.error) == "data range error, hardware alert"


def test_ids_outside_the_protocol_are_refused() -> None:
    with pytest.raises(ValueError, match="255"):
        pkt.ping(255)
