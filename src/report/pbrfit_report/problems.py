# The two ways a report fails, and how each is said: InputProblem (the result file cannot be read as a
# pbrfit result; exit 2, "FILE: error: ...") and RunProblem (the report cannot be made; exit 3,
# "pbrfit: error: ..."). Every message is one line: control characters are escaped.
EXIT_SUCCESS = 0
EXIT_INVALID_INPUT = 2
EXIT_RUN_FAILURE = 3

_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}
_LINE_BREAKING = {"\x85", "\u2028", "\u2029"}  # break lines in some terminals, like control characters


def one_line(text):
    """text with control characters escaped, as pbrfit's own messages do (core/quoted_text.hpp)."""
    out = []
    for c in str(text):
        if c in _NAMED:
            out.append(_NAMED[c])
        elif ord(c) < 32 or ord(c) == 127 or c in _LINE_BREAKING:
            out.append(f"\\x{ord(c):02x}" if ord(c) < 256 else f"\\u{ord(c):04x}")
        else:
            out.append(c)
    return "".join(out)


class InputProblem(Exception):
    def __init__(self, path, message):
        super().__init__(message)
        self.path = path
        self.message = message

    def line(self):
        return f"{one_line(self.path)}: error: {one_line(self.message)}"


class RunProblem(Exception):
    def line(self):
        return f"pbrfit: error: {one_line(str(self))}"
