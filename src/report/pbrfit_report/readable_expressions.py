# Expressions for people, for every kind that prints the gp engine's expressions (symreg, brdf_search).
# A front member's text ("t1 = saturate(...); t1 * t1": docs/results-symreg.md) is
# read by a whitelist over Python's parser: numbers, the output's inputs, temporaries, + - * / and the
# operators of the gp engine, nothing else (the file is input: nothing in it is ever run). It is evaluated on
# the output's training rows (knee_prediction's input columns) with the engine's semantics
# (include/pbrfit/gp/semantics.hpp), and each constant in turn is rounded to the fewest significant digits
# that leave the RMSE as the page prints it (4 digits) unchanged. SymPy then gives the rounded expression as
# LaTeX, with the temporaries substituted and its automatic simplification (like terms and constant
# products combined: those combined constants are shown to 4 digits), for a typeset figure.
import ast
import math

import numpy as np

PRINTED_DIGITS = 4
MAX_DIGITS = 17


def _protected_sqrt(a):
    return np.sqrt(np.abs(a))


FUNCTIONS = {  # name: (arity, numpy meaning)
    "identity": (1, lambda a: a),
    "add": (2, lambda a, b: a + b),
    "sub": (2, lambda a, b: a - b),
    "mul": (2, lambda a, b: a * b),
    "div": (2, lambda a, b: a / b),
    "fma": (3, lambda a, b, c: a * b + c),
    "min": (2, np.minimum),  # both propagate NaN, as the engine's do
    "max": (2, np.maximum),
    "abs": (1, np.abs),
    "neg": (1, np.negative),
    "sqrt": (1, _protected_sqrt),
    "rsqrt": (1, lambda a: 1.0 / _protected_sqrt(a)),
    "exp": (1, np.exp),
    "exp2": (1, np.exp2),
    "log": (1, lambda a: np.log(np.abs(a))),
    "log2": (1, lambda a: np.log2(np.abs(a))),
    "pow": (2, lambda a, b: np.exp2(b * np.log2(np.abs(a)))),
    "sin": (1, np.sin),
    "cos": (1, np.cos),
    "saturate": (1, lambda a: np.clip(a, 0.0, 1.0)),
    "tan": (1, np.tan),
    "asin": (1, np.arcsin),
    "acos": (1, np.arccos),
    "atan": (1, np.arctan),
}
OPERATORS = {ast.Add: np.add, ast.Sub: np.subtract, ast.Mult: np.multiply, ast.Div: np.divide}


class NotReadable(Exception):
    """The text is not an expression of the engine's language."""


def _check(node, names):
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise NotReadable("a constant that is not a number")
    elif isinstance(node, ast.Name):
        if node.id not in names:
            raise NotReadable(f"unknown name {node.id}")
    elif isinstance(node, ast.BinOp):
        if type(node.op) not in OPERATORS:
            raise NotReadable("an operator outside + - * /")
        _check(node.left, names), _check(node.right, names)
    elif isinstance(node, ast.UnaryOp):
        if not isinstance(node.op, (ast.USub, ast.UAdd)):
            raise NotReadable("a unary operator other than -")
        _check(node.operand, names)
    elif isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS or node.keywords or \
                len(node.args) != FUNCTIONS[node.func.id][0]:
            raise NotReadable("a call that is not one of the operators")
        for argument in node.args:
            _check(argument, names)
    else:
        raise NotReadable(f"a {type(node).__name__}")


class Expression:
    """A parsed expression text: statements `name = expression` and a last expression."""

    def __init__(self, text, inputs):
        try:
            module = ast.parse("\n".join(part.strip() for part in text.split(";")), mode="exec")
        except (SyntaxError, ValueError) as error:
            raise NotReadable(str(error)) from error
        if not module.body or not isinstance(module.body[-1], ast.Expr):
            raise NotReadable("no final expression")
        names = set(inputs)
        self.statements = []  # (name or None, expression node)
        for statement in module.body:
            if isinstance(statement, ast.Assign) and len(statement.targets) == 1 and \
                    isinstance(statement.targets[0], ast.Name) and statement is not module.body[-1]:
                _check(statement.value, names)
                names.add(statement.targets[0].id)
                self.statements.append((statement.targets[0].id, statement.value))
            elif isinstance(statement, ast.Expr) and statement is module.body[-1]:
                _check(statement.value, names)
                self.statements.append((None, statement.value))
            else:
                raise NotReadable("a statement that is neither an assignment nor the result")
        self.constants = [n for _, node in self.statements for n in ast.walk(node) if isinstance(n, ast.Constant)]

    def values(self, columns):
        """The expression at every row; columns: {input name: array}."""
        scope = dict(columns)

        def value(node):
            if isinstance(node, ast.Constant):
                return float(node.value)
            if isinstance(node, ast.Name):
                return scope[node.id]
            if isinstance(node, ast.BinOp):
                return OPERATORS[type(node.op)](value(node.left), value(node.right))
            if isinstance(node, ast.UnaryOp):
                return -value(node.operand) if isinstance(node.op, ast.USub) else value(node.operand)
            return FUNCTIONS[node.func.id][1](*(value(a) for a in node.args))

        with np.errstate(all="ignore"):
            for name, node in self.statements:
                result = value(node)
                if name is not None:
                    scope[name] = result
        return np.broadcast_to(np.asarray(result, dtype=np.float64), next(iter(columns.values())).shape)

    def text(self):
        return "; ".join((f"{name} = " if name else "") + ast.unparse(node) for name, node in self.statements)


def rmse(expression, columns, target):
    residual = expression.values(columns) - target
    return float(np.sqrt(np.mean(residual * residual)))


def _printed(value):
    return f"{value:.{PRINTED_DIGITS}g}"


def rounded(text, inputs, columns, target, expected_rmse=None):
    """(readable text, its RMSE): the text with each constant at the fewest significant digits that keep
    the printed RMSE. Raises NotReadable for a text outside the language, or whose RMSE here differs from
    `expected_rmse` (the file's) in its printed digits: then the rows are not the ones it was measured on."""
    expression = Expression(text, inputs)
    full = rmse(expression, columns, target)
    if expected_rmse is not None and np.isfinite(expected_rmse) and _printed(full) != _printed(expected_rmse):
        raise NotReadable(f"its RMSE on the rows here is {full:.6g}, not the file's {expected_rmse:.6g}")
    for constant in expression.constants:
        exact = float(constant.value)
        for digits in range(1, MAX_DIGITS + 1):
            constant.value = float(f"{exact:.{digits - 1}e}")
            if _printed(rmse(expression, columns, target)) == _printed(full):
                break
        else:
            constant.value = exact
    return expression.text(), rmse(expression, columns, target)


def _sympy_form(text, inputs, exact_constants):
    """The expression in SymPy, temporaries substituted (SymPy's automatic simplification applied), and the
    LaTeX names of its inputs; None when SymPy is not installed. exact_constants: integers and pi as such,
    other constants as written; else every constant as a float."""
    try:
        import sympy
    except ImportError:
        return None
    expression = Expression(text, inputs)
    saturate = sympy.Function("sat")
    functions = {
        "identity": lambda a: a, "add": lambda a, b: a + b, "sub": lambda a, b: a - b, "mul": lambda a, b: a * b,
        "div": lambda a, b: a / b, "fma": lambda a, b, c: a * b + c, "min": sympy.Min, "max": sympy.Max,
        "abs": sympy.Abs, "neg": lambda a: -a, "sqrt": lambda a: sympy.sqrt(sympy.Abs(a)),
        "rsqrt": lambda a: 1 / sympy.sqrt(sympy.Abs(a)), "exp": sympy.exp, "exp2": lambda a: 2 ** a,
        "log": lambda a: sympy.log(sympy.Abs(a)), "log2": lambda a: sympy.log(sympy.Abs(a), 2),
        "pow": lambda a, b: sympy.Abs(a) ** b, "sin": sympy.sin, "cos": sympy.cos, "saturate": saturate,
        "tan": sympy.tan, "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan,
    }
    scope = {name: sympy.Symbol(name, real=True) for name in inputs}

    def value(node):
        if isinstance(node, ast.Constant):
            number = float(node.value)
            if exact_constants and number.is_integer() and abs(number) < 2 ** 53:
                return sympy.Integer(int(number))
            if exact_constants and number == math.pi:
                return sympy.pi
            return sympy.Float(repr(number))
        if isinstance(node, ast.Name):
            return scope[node.id]
        if isinstance(node, ast.BinOp):
            a, b = value(node.left), value(node.right)
            return {ast.Add: a + b, ast.Sub: a - b, ast.Mult: a * b, ast.Div: a / b}[type(node.op)]
        if isinstance(node, ast.UnaryOp):
            return -value(node.operand) if isinstance(node.op, ast.USub) else value(node.operand)
        return functions[node.func.id](*(value(a) for a in node.args))

    for name, node in expression.statements:
        result = value(node)
        if name is not None:
            scope[name] = result
    names = {scope[name]: r"\mathrm{" + name.replace("_", r"\_") + "}" for name in inputs}
    return result, names


def latex(text, inputs, exact_constants=False):
    """The expression as LaTeX (SymPy); floats shown to PRINTED_DIGITS (rounded() has already cut each
    written constant to what the error allows; these are the ones SymPy combined). None without SymPy."""
    import_failed = _sympy_form(text, inputs, exact_constants)
    if import_failed is None:
        return None
    import sympy
    result, names = import_failed
    result = result.xreplace({f: sympy.Float(float(f"{float(f):.{PRINTED_DIGITS}g}")) for f in result.atoms(sympy.Float)})
    return sympy.latex(result, full_prec=False, symbol_names=names, mul_symbol="dot")


def plain(text, inputs):
    """The expression as one line of text, simplified by SymPy with integers and pi exact (pow(a, b) reads
    Abs(a)**b and sqrt(a) sqrt(Abs(a)), as the engine protects them; sat is saturate); the text as written
    when SymPy is not installed or cannot read it."""
    try:
        form = _sympy_form(text, inputs, exact_constants=True)
    except (NotReadable, RecursionError):
        return text
    if form is None:
        return text
    import sympy
    return sympy.sstr(form[0])
