"""exactsym: the leader-election and gathering algorithms of Gan Chaudhuri and
Mukhopadhyaya, *Leader Election and Gathering for Asynchronous Transparent Fat Robots
without Chirality*, made executable with exact arithmetic and checked against the truth."""

__version__ = "0.1.0"
