"""Writes reeds_shepp_ompl.txt: Reeds-Shepp lengths and poses computed by OMPL.

The reference is OMPL's ReedsSheppStateSpace (OMPL 2.0.1, the `ompl` package on PyPI, BSD
3-Clause licence), which nobody in this project wrote. Run from this folder with that package
installed (`pip install ompl==2.0.1`):

    python3 reeds_shepp_ompl.py > reeds_shepp_ompl.txt

The draw is seeded, so the file comes out the same each time.
"""

import math
import random

from ompl import base as ob

HEADER = """\
# Reeds-Shepp shortest paths computed by OMPL's ReedsSheppStateSpace (OMPL 2.0.1, the Python
# package `ompl` on PyPI; BSD 3-Clause licence, Copyright (c) 2010, Rice University; all rights
# reserved), written by reeds_shepp_ompl.py beside this file from a seeded draw.
#
# Each case: the turning radius r, the start pose (x0, y0, th0), the goal pose (x1, y1, th1), the
# length of the shortest path (OMPL's distance), then the pose OMPL interpolates at a quarter, a
# half and three quarters of the path's length (headings in [-pi, pi)).
#
# Redistribution and use in source and binary forms, with or without modification, are permitted
# provided that the following conditions are met: Redistributions of source code must retain the
# above copyright notice, this list of conditions and the following disclaimer. Redistributions in
# binary form must reproduce the above copyright notice, this list of conditions and the following
# disclaimer in the documentation and/or other materials provided with the distribution. Neither
# the name of the Rice University nor the names of its contributors may be used to endorse or
# promote products derived from this software without specific prior written permission. THIS
# SOFTWARE IS PROVIDED BY THE COPYRIGHT HOLDERS AND CONTRIBUTORS "AS IS" AND ANY EXPRESS OR IMPLIED
# WARRANTIES, INCLUDING, BUT NOT LIMITED TO, THE IMPLIED WARRANTIES OF MERCHANTABILITY AND FITNESS
# FOR A PARTICULAR PURPOSE ARE DISCLAIMED. IN NO EVENT SHALL THE COPYRIGHT HOLDER OR CONTRIBUTORS
# BE LIABLE FOR ANY DIRECT, INDIRECT, INCIDENTAL, SPECIAL, EXEMPLARY, OR CONSEQUENTIAL DAMAGES
# (INCLUDING, BUT NOT LIMITED TO, PROCUREMENT OF SUBSTITUTE GOODS OR SERVICES; LOSS OF USE, DATA,
# OR PROFITS; OR BUSINESS INTERRUPTION) HOWEVER CAUSED AND ON ANY THEORY OF LIABILITY, WHETHER IN
# CONTRACT, STRICT LIABILITY, OR TORT (INCLUDING NEGLIGENCE OR OTHERWISE) ARISING IN ANY WAY OUT OF
# THE USE OF THIS SOFTWARE, EVEN IF ADVISED OF THE POSSIBILITY OF SUCH DAMAGE.
#
r x0 y0 th0 x1 y1 th1 length x25 y25 th25 x50 y50 th50 x75 y75 th75"""


def main():
    rng = random.Random(20261204)
    print(HEADER)
    # Far apart (straight pieces), near (the words of three and four turns), and very near
    # (within a radius), at a few radii.
    blocks = [(500, 10.0, 1.0), (300, 2.5, 1.0), (200, 0.8, 1.0), (200, 6.0, None)]
    spaces = {}
    for count, extent, radius in blocks:
        for _ in range(count):
            r = radius if radius is not None else rng.choice([0.25, 0.5, 2.0, 3.7])
            if r not in spaces:
                space = ob.ReedsSheppStateSpace(r)
                bounds = ob.RealVectorBounds(2)
                bounds.setLow(-1000.0)
                bounds.setHigh(1000.0)
                space.setBounds(bounds)
                spaces[r] = space
            space = spaces[r]
            a, b, out = space.allocState(), space.allocState(), space.allocState()
            start = [rng.uniform(-extent, extent), rng.uniform(-extent, extent), rng.uniform(-math.pi, math.pi)]
            goal = [rng.uniform(-extent, extent), rng.uniform(-extent, extent), rng.uniform(-math.pi, math.pi)]
            for state, (x, y, th) in ((a, start), (b, goal)):
                state.setX(x)
                state.setY(y)
                state.setYaw(th)
            fields = [r, *start, *goal, space.distance(a, b)]
            for t in (0.25, 0.5, 0.75):
                space.interpolate(a, b, t, out)
                fields += [out.getX(), out.getY(), out.getYaw()]
            print(" ".join(repr(float(f)) for f in fields))


if __name__ == "__main__":
    main()
