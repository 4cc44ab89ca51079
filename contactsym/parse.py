"""A safe parser for the formulas a user writes as text, and the API's text boundary.

Text never reaches ``eval``, ``sympify`` or ``parse_expr``. :func:`parse_expression`
reads a small grammar with its own tokenizer and a recursive-descent parser, and builds
the SymPy expression directly:

.. code-block:: text

    expression := term (("+" | "-") term)*
    term       := unary (("*" | "/") unary)*
    unary      := ("+" | "-") unary | power
    power      := atom (("^" | "**") unary)?          right-associative, -x^2 = -(x^2)
    atom       := number | name | name "(" expression ("," expression)* ")" | "(" expression ")"
    name       := letter (letter | digit | "_")* "'"*     x' is the rate of the coordinate x

Names resolve only to the symbols the caller declares (so a typo is an error, not a new
symbol) and to the functions of :data:`FUNCTIONS` and the constant ``pi``. Decimal
numbers become exact rationals (0.1 is 1/10). Input longer than :data:`MAX_LENGTH`
characters or nested deeper than :data:`MAX_DEPTH` is refused before any work.

The Python API takes SymPy objects and numbers only: :func:`sympy_only` is the check
that its entry points run on their inputs, and a string there is an error that points
here.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from dataclasses import dataclass

import sympy as sp

from .errors import ContactsymError

__all__ = ["FUNCTIONS", "MAX_DEPTH", "MAX_LENGTH", "ParseError", "parse_expression", "sympy_only"]

#: The functions a formula may call, by name, with their number of arguments.
FUNCTIONS = {
    "sin": (sp.sin, 1),
    "cos": (sp.cos, 1),
    "tan": (sp.tan, 1),
    "cot": (sp.cot, 1),
    "asin": (sp.asin, 1),
    "acos": (sp.acos, 1),
    "atan": (sp.atan, 1),
    "atan2": (sp.atan2, 2),
    "sinh": (sp.sinh, 1),
    "cosh": (sp.cosh, 1),
    "tanh": (sp.tanh, 1),
    "sqrt": (sp.sqrt, 1),
    "exp": (sp.exp, 1),
    "log": (sp.log, 1),
    "Abs": (sp.Abs, 1),
    "sign": (sp.sign, 1),
}

#: Constants every formula may use.
CONSTANTS = {"pi": sp.pi}

#: Longest formula accepted, in characters.
MAX_LENGTH = 10_000
#: Deepest nesting accepted (parentheses, unary signs, powers, calls).
MAX_DEPTH = 100
#: Largest power of ten in a number, and largest exponent of a number's power.
MAX_EXPONENT = 300

_TOKEN = re.compile(
    r"(?P<space>\s+)|(?P<number>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)|(?P<name>[A-Za-z][A-Za-z0-9_]*'*)"
    r"|(?P<op>\*\*|[-+*/^(),])"
)


class ParseError(ContactsymError):
    """A formula that is not in the grammar of :mod:`contactsym.parse`, or names an unknown symbol."""


@dataclass(frozen=True)
class _Token:
    kind: str  # 'number', 'name', 'op' or 'end'
    text: str
    column: int  # 0-based


def _where(source: str, line: int, column: int) -> str:
    return f"{source}:{line}:{column + 1}"


def _short(text: str, limit: int = 40) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _tokens(text: str, fail) -> list[_Token]:
    tokens, position = [], 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None:
            bad = text[position]
            hint = (
                " (attributes, strings, brackets and other Python are not formulas)" if bad in ".[]{}'\"_:=<>" else ""
            )
            fail(position, f"unexpected character {bad!r}{hint}; expected a number, a name, an operator or '('")
        if match.lastgroup != "space":
            tokens.append(_Token(match.lastgroup, match.group(), position))
        position = match.end()
    tokens.append(_Token("end", "", len(text)))
    return tokens


class _Parser:
    """Recursive descent over the tokens; each method parses one rule of the grammar."""

    def __init__(self, text: str, names: Mapping, source: str, line: int, column: int):
        self.text, self.names, self.source, self.line, self.column = text, names, source, line, column
        self.tokens = _tokens(text, self.fail)
        self.position = 0
        self.depth = 0

    def fail(self, column: int, message: str):
        raise ParseError(f"{_where(self.source, self.line, self.column + column)}: {message}.")

    @property
    def token(self) -> _Token:
        return self.tokens[self.position]

    def take(self, *texts: str) -> bool:
        if self.token.kind == "op" and self.token.text in texts:
            self.position += 1
            return True
        return False

    def expect(self, text: str, what: str) -> None:
        if not self.take(text):
            self.fail(self.token.column, f"expected {what}, found {self._found()}")

    def _found(self) -> str:
        return "the end of the formula" if self.token.kind == "end" else repr(_short(self.token.text))

    def nest(self):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(self.token.column, f"nested more than {MAX_DEPTH} deep; write the formula in simpler parts")

    def parse(self) -> sp.Expr:
        if self.token.kind == "end":
            self.fail(0, "empty formula; expected a number, a name or '('")
        expr = self.expression()
        if self.token.kind != "end":
            self.fail(self.token.column, f"expected an operator or the end of the formula, found {self._found()}")
        if expr.has(sp.zoo, sp.nan, sp.oo, sp.S.NegativeInfinity):
            self.fail(
                0, f"the formula evaluates to {_short(str(expr))}, which is not finite; check for a division by zero"
            )
        if expr.has(sp.I):
            self.fail(
                0, f"the formula evaluates to {_short(str(expr))}, which is not real (a root of a negative number?)"
            )
        return expr

    def expression(self) -> sp.Expr:
        terms = [self.term()]  # summed once at the end: adding term by term is quadratic
        while True:
            if self.take("+"):
                terms.append(self.term())
            elif self.take("-"):
                terms.append(-self.term())
            else:
                return sp.Add(*terms)

    def term(self) -> sp.Expr:
        factors = [self.unary()]
        while True:
            if self.take("*"):
                factors.append(self.unary())
            elif self.take("/"):
                column = self.token.column
                divisor = self.unary()
                if divisor == 0:
                    self.fail(column, "division by zero")
                factors.append(1 / divisor)
            else:
                return sp.Mul(*factors)

    def unary(self) -> sp.Expr:
        self.nest()
        if self.take("-"):
            expr = -self.unary()
        elif self.take("+"):
            expr = self.unary()
        else:
            expr = self.power()
        self.depth -= 1
        return expr

    def power(self) -> sp.Expr:
        base = self.atom()
        if self.take("^", "**"):
            column = self.token.column
            exponent = self.unary()
            # a number to a huge power would be computed in full (9^9^9): refuse it instead
            if exponent.is_Rational and base.is_Rational:
                bits = (base.p.bit_length() + base.q.bit_length()) * abs(exponent)
                if abs(exponent) > MAX_EXPONENT or bits > 64 * MAX_EXPONENT:
                    self.fail(column, f"the power {_short(str(exponent))} of {_short(str(base))} is too large")
            return base**exponent
        return base

    def atom(self) -> sp.Expr:
        token = self.token
        if token.kind == "number":
            self.position += 1
            mantissa, _, exponent = token.text.lower().partition("e")
            if abs(int(exponent or 0)) > MAX_EXPONENT or len(mantissa) > MAX_EXPONENT:
                self.fail(token.column, f"the number {_short(token.text)} is out of range (at most 1e{MAX_EXPONENT})")
            return sp.Integer(token.text) if token.text.isdigit() else sp.Rational(token.text)
        if token.kind == "name":
            self.position += 1
            if token.text in FUNCTIONS and self.token.text == "(":
                return self.call(token)
            return self.name(token)
        if self.take("("):
            self.nest()
            expr = self.expression()
            self.expect(")", "')' to close the '('")
            self.depth -= 1
            return expr
        self.fail(token.column, f"expected a number, a name or '(', found {self._found()}")

    def call(self, token: _Token) -> sp.Expr:
        function, arity = FUNCTIONS[token.text]
        self.expect("(", "'('")
        self.nest()
        arguments = [self.expression()]
        while self.take(","):
            arguments.append(self.expression())
        self.expect(")", f"',' or ')' to close {token.text}(")
        self.depth -= 1
        if len(arguments) != arity:
            self.fail(token.column, f"{token.text} takes {arity} argument(s), got {len(arguments)}")
        return function(*arguments)

    def name(self, token: _Token) -> sp.Expr:
        if token.text in self.names:
            return self.names[token.text]
        if token.text in CONSTANTS:
            return CONSTANTS[token.text]
        if token.text in FUNCTIONS:
            self.fail(token.column, f"{token.text} is a function; write {token.text}(...)")
        known = sorted(self.names)
        close = difflib.get_close_matches(token.text, known, n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        listed = ", ".join(_short(n, 20) for n in known[:30]) + (", ..." if len(known) > 30 else "")
        self.fail(token.column, f"unknown name {_short(token.text)!r}; {hint}declared names: {listed or 'none'}")


def parse_expression(
    text: str, names: Mapping[str, sp.Basic] | None = None, *, source: str = "<formula>", line: int = 1, column: int = 0
) -> sp.Expr:
    """Parse a formula of the safe grammar into a SymPy expression.

    Parameters
    ----------
    text : str
        The formula, e.g. ``"m*(x'^2 + y'^2)/2 - m*g*y"``.
    names : mapping of str to SymPy object
        The names the formula may use and what each stands for (a Symbol with its
        assumptions, a coordinate ``x(t)``, a rate ``x'``, an applied function).
    source, line, column : str, int, int
        Where the text sits, for messages ``source:line:column``; ``column`` is the
        0-based column of the formula's first character.

    Returns
    -------
    sympy.Expr

    Raises
    ------
    ParseError
        Text outside the grammar, an unknown name, too long or nested too deep.

    Examples
    --------
    >>> import sympy as sp
    >>> m, g = sp.symbols("m g", positive=True)
    >>> parse_expression("-m*g^2/2 + 0.5*sin(pi/6)", {"m": m, "g": g})
    -g**2*m/2 + 1/4
    >>> parse_expression("__import__('os')", {"m": m})
    Traceback (most recent call last):
    ...
    contactsym.parse.ParseError: <formula>:1:1: unexpected character '_' (attributes, strings, brackets and other Python are not formulas); expected a number, a name, an operator or '('.
    >>> parse_expression("m*gg", {"m": m, "g": g}, source="my.toml", line=7, column=12)
    Traceback (most recent call last):
    ...
    contactsym.parse.ParseError: my.toml:7:15: unknown name 'gg'; did you mean 'g'? declared names: g, m.
    """
    where_ok = isinstance(source, str) and len(source) <= 200 and all(type(n) is int and n >= 0 for n in (line, column))
    if not where_ok or not (names is None or isinstance(names, Mapping)):
        raise ParseError(
            "parse_expression: names is a mapping {name: symbol}, source a short name, line and column >= 0."
        )
    names = dict(names or {})
    if not isinstance(text, str):
        raise ParseError(f"{_where(source, line, column)}: a formula must be text, not {type(text).__name__}.")
    if len(text) > MAX_LENGTH:
        raise ParseError(
            f"{_where(source, line, column)}: the formula has {len(text)} characters, more than {MAX_LENGTH}; "
            "split it into named parts."
        )
    with sp.evaluate(True):
        return _Parser(text, names, source, line, column).parse()


def sympy_only(value, what: str):
    """``value`` as a SymPy object, if it is one or a number; text and other objects are refused.

    The Python API calls this on every expression it receives, so no string reaches
    ``sympify``. Text formulas go through :func:`parse_expression`, with declared names.

    Examples
    --------
    >>> sympy_only(0.5, "eps"), sympy_only(sp.Symbol("x") + 1, "a")
    (0.500000000000000, x + 1)
    >>> sympy_only("__import__('os').system('true')", "eps")
    Traceback (most recent call last):
    ...
    contactsym.parse.ParseError: eps is text ("__import__('os').system('true')"); contactsym never evaluates text: pass a SymPy expression or a number, or parse a formula with contactsym.parse_expression(text, names).
    """
    if isinstance(value, (str, bytes)):
        raise ParseError(
            f"{what} is text ({_short(repr(value))}); contactsym never evaluates text: pass a SymPy expression "
            "or a number, or parse a formula with contactsym.parse_expression(text, names)."
        )
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return value
    try:
        return sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError, ValueError) as error:
        raise ParseError(
            f"{what} = {_short(repr(value))} of type {type(value).__name__} is neither a SymPy object nor a number."
        ) from error
