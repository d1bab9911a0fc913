"""Seconds to first-touch 1 GiB of new anonymous memory in 4 KiB pages (no huge-page advice).

On this project's virtual machine the figure changes from day to day (under 0.6 s on days of
cheap page faults, 3 to 4 s on days of costly ones), and with it every first run that writes new
memory: scripts/run-benchmark.sh records it with the machine (Documentation/speed.md, "Page
faults on this virtual machine"). Runs with any Python 3.
"""
import mmap
import time

SIZE = 1 << 30
PAGE = 4096

memory = mmap.mmap(-1, SIZE)
start = time.perf_counter()
for offset in range(0, SIZE, PAGE):
    memory[offset] = 1
seconds = time.perf_counter() - start
memory.close()
print(f"page faults: 1 GiB of new memory first touched in 4 KiB pages in {seconds:.2f} s")
