"""
More than two contacts: three fingers on a round part, a four-finger hand
=========================================================================

The paper stops at two contacts.  For n contacts with Coulomb friction the least sum of
normal forces is again the outer envelope of Thales circles on O q, one for each vertex q
of a convex polygon Q (:mod:`graspcompass.ncontact`).  Left: three fingers 120° apart
on a round part (μ = 1/2): Q is a hexagon, all six circles touch the envelope.  Right: a
thumb below and three fingers above a 2 × 1 part: five vertices, two dual vertices
redundant.  Each vertex is constructed with parallels through the contacts' cost points
and one quarter turn (``graspcompass steps --contact ...``); the worst squeeze of the
gripper over all orientations is ``F_e max |q|`` (``graspcompass size --contact ...``).
To drag the contacts and their normals in a browser, write the n-contact web page:
``graspcompass export --contact ... --format html -o hand.html``.
"""

import matplotlib.pyplot as plt

from graspcompass.ncontact import NContactGrasp
from graspcompass.render.ncontact import draw_ncontact

three = NContactGrasp(
    [
        ("1", "0", "180deg", "1/2"),
        ("-1/2", "sqrt(3)/2", "-60deg", "1/2"),
        ("-1/2", "-sqrt(3)/2", "60deg", "1/2"),
    ]
)
hand = NContactGrasp(
    [
        ("0", "-1/2", "90deg", "3/5"),
        ("-3/4", "1/2", "-90deg", "2/5"),
        ("0", "1/2", "-90deg", "2/5"),
        ("3/4", "1/2", "-90deg", "2/5"),
    ]
)
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 5.2))
draw_ncontact(three, ax=a, title="three fingers, μ = 1/2: Q is a hexagon")
draw_ncontact(hand, ax=b, title="a four-finger hand: five vertices of Q")
for g, ax in ((three, a), (hand, b)):
    value, theta = g.worst()
    ax.set_xlabel(
        f"worst load direction θ = {float(theta) * 57.29578:.1f}°, max |q| = {float(value):.4f}"
    )
fig.tight_layout()
plt.show()
