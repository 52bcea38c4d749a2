"""The module's exceptions: the three tiers of vahf/core/error.h.

Each carries ``file``, ``field``, ``value`` and ``rule``; ``str(error)`` is the
line the command prints after ``vahf: error:``.
"""


class Error(Exception):
    """Base of vahf's exceptions."""

    file = ""
    field = ""
    value = ""
    rule = ""


class InputError(Error, ValueError):
    """Bad input: which file, where in it (a JSON pointer or "line N"),
    the offending value and the rule it breaks (the command's exit 2)."""

    def __init__(self, message, file, field, value, rule):
        super().__init__(message)
        self.file = file
        self.field = field
        self.value = value
        self.rule = rule


class ComputationError(Error, RuntimeError):
    """Valid input, but the computation cannot give a result (the
    command's exit 1). ``reason``: too_few_values, zero_variance,
    out_of_domain or refused; ``rule`` holds the message."""

    def __init__(self, message, reason):
        super().__init__(message)
        self.reason = reason
        self.rule = message


class InternalError(Error, AssertionError):
    """A failed internal check: a bug in vahf, not in the input (the
    command aborts; the module raises this and the interpreter lives on).
    ``file`` and ``line`` are the source's, ``field`` is "line N",
    ``value`` the condition and ``rule`` the check's message."""

    def __init__(self, message, file, line, condition, check_message):
        super().__init__(message)
        self.file = file
        self.line = line
        self.field = "line %d" % line
        self.value = condition
        self.condition = condition
        self.rule = check_message
