"""The angrybirds domain: Science Birds levels (the paper's demonstration domain)."""

from physc.domains.angrybirds.vocabulary import VOCABULARY


class AngryBirds:
    name = "angrybirds"
    description = "Angry Birds levels in the Science Birds format (the paper's domain)"
    vocabulary = VOCABULARY


DOMAIN = AngryBirds()
