"""Hypothesis profiles of the suite: reproducible by default, seeded on demand.

- ``ci`` (the default): derandomized, so every run (and every CI machine) draws the same
  examples; no example database, so a run depends on the code alone; a failure prints its
  example and the ``@reproduce_failure`` blob.
- ``seeded``: the same without derandomization, for runs with other examples:
  ``pytest --hypothesis-profile=seeded --hypothesis-seed=N`` draws a different, reproducible
  set for each N (a seed does not override ``derandomize``, hence the second profile).

``HYPOTHESIS_PROFILE=seeded`` in the environment selects the second one too. Random numbers
outside hypothesis come from seeded generators (``np.random.default_rng(seed)``,
``random.Random(seed)``) in every test.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None, print_blob=True, deadline=None)
settings.register_profile("seeded", derandomize=False, database=None, print_blob=True, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
