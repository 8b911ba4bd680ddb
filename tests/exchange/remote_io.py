#!/usr/bin/python3
"""A simulated Modbus TCP remote I/O coupler, served by Debian's python3-pymodbus, for the tests
of iecoop's modbus_client (tests/exchange/modbus_client_test.cpp).

    remote_io.py PORT [--delay SECONDS] [--size N]

Its data model has N of each: coils, discrete inputs, holding registers, input registers,
addressed from 0. It is wired as a loopback coupler: every 2 ms its inputs follow its outputs
(discrete input i := coil i, input register i := holding register i, for i < 16); input register
20 counts up every 10 ms (live data). With --delay every read of its data takes that long (a
slow device: the responses come late). It prints "remote_io: serving on PORT" when it is about
to listen (wait for the port too) and runs until killed.
"""
import argparse
import asyncio
import sys
import time

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server import StartAsyncTcpServer


class SlowBlock(ModbusSequentialDataBlock):
    """A data block whose reads take `delay` seconds (blocking the server: a slow device)."""

    def __init__(self, address, values, delay):
        super().__init__(address, values)
        self.delay = delay

    def getValues(self, address, count=1):  # noqa: N802 (pymodbus's name)
        if self.delay > 0:
            time.sleep(self.delay)
        return super().getValues(address, count)


async def wiring(store):
    """The coupler's field side: inputs follow outputs; a counter runs."""
    ticks = 0
    while True:
        await asyncio.sleep(0.002)
        ticks += 1
        coils = ModbusSequentialDataBlock.getValues(store.store["c"], 0, 16)
        holding = ModbusSequentialDataBlock.getValues(store.store["h"], 0, 16)
        ModbusSequentialDataBlock.setValues(store.store["d"], 0, coils)
        ModbusSequentialDataBlock.setValues(store.store["i"], 0, holding)
        if ticks % 5 == 0:
            counter = ModbusSequentialDataBlock.getValues(store.store["i"], 20, 1)[0]
            ModbusSequentialDataBlock.setValues(store.store["i"], 20, [(counter + 1) & 0xFFFF])


async def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("port", type=int)
    parser.add_argument("--delay", type=float, default=0.0)
    parser.add_argument("--size", type=int, default=64)
    args = parser.parse_args()

    def block():
        return SlowBlock(0, [0] * args.size, args.delay)

    store = ModbusSlaveContext(di=block(), co=block(), hr=block(), ir=block(), zero_mode=True)
    context = ModbusServerContext(slaves=store, single=True)
    # allow_reuse_address: a coupler started again binds its port at once, even while connections
    # of the one before linger in TIME_WAIT (pymodbus's default is not to).
    server = await StartAsyncTcpServer(
        context=context, address=("127.0.0.1", args.port), defer_start=True, allow_reuse_address=True
    )
    asyncio.get_running_loop().create_task(wiring(store))
    print(f"remote_io: serving on {args.port}", flush=True)
    await server.serve_forever()


if __name__ == "__main__":
    try:
        asyncio.run(main())
    except KeyboardInterrupt:
        sys.exit(0)
