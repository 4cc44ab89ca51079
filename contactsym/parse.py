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
numbers become exact rationals (0.1 is 1/10).

A formula is text a user writes, so its size is capped before it can cost minutes or
memory later in the pipeline; each refusal is a :class:`ParseError` that names the cap.
The caps are module constants, read at each call. To read a formula beyond one, raise it:
on the command line ``contactsym --limit max_degree=100 ...`` (the lower-case name of the
cap), in Python ``with contactsym.parse.formula_caps(max_degree=100): ...`` or, for the
whole process, ``contactsym.parse.MAX_DEGREE = 100``.

- :data:`MAX_LENGTH` characters, nested at most :data:`MAX_DEPTH` deep (refused before
  any work), with at most :data:`MAX_CALL_DEPTH` function calls inside one another;
- numbers, written or made by the arithmetic, below ``10**MAX_DIGITS`` (numerator and
  denominator), and a number's power at most :data:`MAX_EXPONENT`;
- a power of anything that is not a number (``(1 + Y)^n``) at most :data:`MAX_DEGREE`,
  also where SymPy combines powers (``((1 + Y)^30)^30`` is a power 900);
- the value of a number built from functions and powers (``exp(exp(10))``) at most
  ``10**MAX_EXPONENT`` in size, so that it is still a floating-point number.

The Python API takes SymPy objects and numbers only: :func:`sympy_only` is the check
that its entry points run on their inputs, and a string there is an error that points
here. It, the tokenizer and :data:`FUNCTIONS` live in :mod:`contactsym.boundary.formula_text`.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator, Mapping
from contextlib import AbstractContextManager, contextmanager

import sympy as sp

from .boundary.formula_text import CONSTANTS, FUNCTIONS, Token, shown, sympy_only, tokens, where
from .errors import ParseError
from .validate import cut

__all__ = [
    "CAPS",
    "FUNCTIONS",
    "MAX_CALL_DEPTH",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "ParseError",
    "formula_caps",
    "parse_expression",
    "sympy_only",
]

#: Longest formula accepted, in characters.
MAX_LENGTH = 10_000
#: Deepest nesting accepted (parentheses, unary signs, powers, calls).
MAX_DEPTH = 100
#: Largest power of ten in a number, and largest exponent of a number's power.
MAX_EXPONENT = 300
#: Most decimal digits of a number (numerator or denominator), written or computed: 1e300 has 301.
MAX_DIGITS = 301
#: Largest exponent (numerator or denominator) of a power whose base is not a number.
MAX_DEGREE = 32
#: Most function calls nested inside one another.
MAX_CALL_DEPTH = 8

#: The caps by the names ``--limit`` and :func:`formula_caps` take (``max_degree`` is MAX_DEGREE).
CAPS = ("max_length", "max_depth", "max_exponent", "max_digits", "max_degree", "max_call_depth")


def _how_to_raise(name: str) -> str:
    """How to raise the cap ``name`` (``MAX_DEGREE``): the command line's option and Python's."""
    return f"raise it with --limit {name.lower()}=N (in Python: parse.formula_caps)"


def formula_caps(**caps: int) -> AbstractContextManager[None]:
    """The caps of this module set to ``caps`` (by their lower-case names, :data:`CAPS`) inside
    the block and restored after it: how a larger formula is read on purpose.

    Examples
    --------
    >>> N = sp.Symbol("N")
    >>> with formula_caps(max_degree=40):
    ...     parse_expression("N^40", {"N": N})
    N**40
    >>> try:
    ...     parse_expression("N^40", {"N": N})
    ... except ParseError as error:
    ...     print(str(error).split(": ", 2)[2].split(";")[0])
    more than contactsym.parse.MAX_DEGREE = 32 allows
    """
    for name, value in caps.items():
        if name not in CAPS:
            close = difflib.get_close_matches(name, CAPS, n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise ParseError(f"{cut(name)} is not a cap of a formula{hint}; the caps are {', '.join(CAPS)}.")
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise ParseError(f"{name} = {cut(repr(value))}: a cap is a whole number >= 1.")
    return _caps_in_force(caps)  # checked now, in force when the block is entered


@contextmanager
def _caps_in_force(caps: dict) -> Iterator[None]:
    saved = {name: globals()[name.upper()] for name in caps}
    globals().update({name.upper(): value for name, value in caps.items()})
    try:
        yield
    finally:
        globals().update({name.upper(): value for name, value in saved.items()})


class _Parser:
    """Recursive descent over the tokens; each method parses one rule of the grammar."""

    def __init__(self, text: str, names: Mapping, source: str, line: int, column: int):
        self.text, self.names, self.source, self.line, self.column = text, names, source, line, column
        self.tokens = tokens(text, self.fail)
        self.position = 0
        self.depth = 0
        self.calls = 0  # function calls open around the current token

    def fail(self, column: int, message: str):
        raise ParseError(f"{where(self.source, self.line, self.column + column)}: {message}.")

    @property
    def token(self) -> Token:
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
        return "the end of the formula" if self.token.kind == "end" else repr(cut(self.token.text))

    def nest(self):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(
                self.token.column,
                f"nested more than contactsym.parse.MAX_DEPTH = {MAX_DEPTH} deep; write the formula in simpler "
                f"parts, or {_how_to_raise('MAX_DEPTH')}",
            )

    # --- caps on what a formula may cost (see the module's documentation) ------------

    def cap(self, column: int, what: str, name: str, fix: str):
        value = globals()[name]
        self.fail(
            column, f"{what}: more than contactsym.parse.{name} = {value} allows; {fix}, or {_how_to_raise(name)}"
        )

    def bounded(self, expr: sp.Expr, column: int) -> sp.Expr:
        """``expr``, checked where numbers are made: digits of a rational, size of any other number."""
        if expr.is_Rational:
            if max(abs(expr.p), expr.q) >= 10**MAX_DIGITS:
                self.cap(column, shown(expr), "MAX_DIGITS", "use smaller numbers")
        elif expr.is_number:
            if expr.has(sp.zoo, sp.nan, sp.oo, sp.S.NegativeInfinity):
                self.fail(column, f"{cut(str(expr))} is not finite; check for a division by zero")
            try:
                real, imaginary = expr.evalf(15).as_real_imag()
                beyond = real.is_Number and bool(abs(real) > sp.Integer(10) ** MAX_EXPONENT)
            except (ArithmeticError, ValueError, TypeError, RecursionError):  # mpmath beyond its range
                real, imaginary, beyond = None, sp.S.Zero, True
            if beyond:
                self.cap(
                    column,
                    f"the number {cut(str(expr))} is larger than 1e{MAX_EXPONENT}",
                    "MAX_EXPONENT",
                    "use smaller numbers",
                )
            if imaginary.is_Number and imaginary != 0:
                self.fail(
                    column,
                    f"{cut(str(expr))} is not a real number (its value is {cut(str(real + sp.I * imaginary))})",
                )
        return expr

    def degrees_bounded(self, expr: sp.Expr) -> None:
        """No power of a non-number above MAX_DEGREE, also where SymPy combined two powers."""
        for node in sp.preorder_traversal(expr):
            if node.is_Pow and node.exp.is_Rational and not node.base.is_number:
                if max(abs(node.exp.p), node.exp.q) > MAX_DEGREE:
                    self.cap(
                        0,
                        f"the power {shown(node.exp)} of {cut(str(node.base))} (powers combined)",
                        "MAX_DEGREE",
                        "write a lower power",
                    )
            elif node.is_Rational:
                self.bounded(node, 0)

    def parse(self) -> sp.Expr:
        if self.token.kind == "end":
            self.fail(0, "empty formula; expected a number, a name or '('")
        expr = self.expression()
        if self.token.kind != "end":
            self.fail(self.token.column, f"expected an operator or the end of the formula, found {self._found()}")
        self.degrees_bounded(expr)
        if expr.has(sp.zoo, sp.nan, sp.oo, sp.S.NegativeInfinity):
            self.fail(
                0, f"the formula evaluates to {cut(str(expr))}, which is not finite; check for a division by zero"
            )
        if expr.has(sp.I):
            self.fail(0, f"the formula evaluates to {cut(str(expr))}, which is not real (a root of a negative number?)")
        return expr

    def expression(self) -> sp.Expr:
        column = self.token.column
        terms = [self.term()]  # summed once at the end: adding term by term is quadratic
        while True:
            if self.take("+"):
                terms.append(self.term())
            elif self.take("-"):
                terms.append(-self.term())
            else:
                return self.bounded(sp.Add(*terms), column)

    def term(self) -> sp.Expr:
        start = self.token.column
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
                return self.bounded(sp.Mul(*factors), start)

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
            if exponent.is_Rational:
                self.power_bounded(base, exponent, column)
            return self.bounded(base**exponent, column)
        return base

    def power_bounded(self, base: sp.Expr, exponent: sp.Rational, column: int) -> None:
        """Refuse a power before SymPy computes it: a number's in full (9^9^9), a symbol's later, in the pipeline."""
        size = max(abs(exponent.p), exponent.q)
        power = f"the power {shown(exponent)} of {cut(str(base))}"
        if base.is_Rational:
            bits = (base.p.bit_length() + base.q.bit_length()) * abs(exponent)
            if abs(exponent) > MAX_EXPONENT or bits > 64 * MAX_EXPONENT:
                self.cap(column, power, "MAX_EXPONENT", "write a smaller power")
        elif base.is_number:
            if size > MAX_EXPONENT:
                self.cap(column, power, "MAX_EXPONENT", "write a smaller power")
        elif size > MAX_DEGREE:
            self.cap(column, power, "MAX_DEGREE", "write a lower power")

    def atom(self) -> sp.Expr:
        token = self.token
        if token.kind == "number":
            self.position += 1
            mantissa, _, exponent = token.text.lower().partition("e")
            if len(exponent) > 6 or abs(int(exponent or 0)) > MAX_EXPONENT or len(mantissa) > MAX_EXPONENT:
                self.cap(
                    token.column,
                    f"the number {cut(token.text)} is out of range",
                    "MAX_EXPONENT",
                    "use smaller numbers",
                )
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

    def call(self, token: Token) -> sp.Expr:
        function, arity = FUNCTIONS[token.text]
        self.expect("(", "'('")
        self.nest()
        self.calls += 1
        if self.calls > MAX_CALL_DEPTH:
            self.cap(token.column, "function calls nested too deep", "MAX_CALL_DEPTH", "name a part")
        arguments = [self.expression()]
        while self.take(","):
            arguments.append(self.expression())
        self.expect(")", f"',' or ')' to close {token.text}(")
        self.depth -= 1
        self.calls -= 1
        if len(arguments) != arity:
            self.fail(token.column, f"{token.text} takes {arity} argument(s), got {len(arguments)}")
        return self.bounded(function(*arguments), token.column)

    def name(self, token: Token) -> sp.Expr:
        if token.text in self.names:
            return self.names[token.text]
        if token.text in CONSTANTS:
            return CONSTANTS[token.text]
        if token.text in FUNCTIONS:
            self.fail(token.column, f"{token.text} is a function; write {token.text}(...)")
        known = sorted(self.names)
        close = difflib.get_close_matches(token.text, known, n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        listed = ", ".join(cut(n, 20) for n in known[:30]) + (", ..." if len(known) > 30 else "")
        self.fail(token.column, f"unknown name {cut(token.text)!r}; {hint}declared names: {listed or 'none'}")


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
    contactsym.errors.ParseError: <formula>:1:1: unexpected character '_' (attributes, strings, brackets and other Python are not formulas); expected a number, a name, an operator or '('.
    >>> parse_expression("m*gg", {"m": m, "g": g}, source="my.toml", line=7, column=12)
    Traceback (most recent call last):
    ...
    contactsym.errors.ParseError: my.toml:7:15: unknown name 'gg'; did you mean 'g'? declared names: g, m.
    """
    where_ok = isinstance(source, str) and len(source) <= 200 and all(type(n) is int and n >= 0 for n in (line, column))
    if not where_ok or not (names is None or isinstance(names, Mapping)):
        raise ParseError(
            "parse_expression: names is a mapping {name: symbol}, source a short name, line and column >= 0."
        )
    names = dict(names or {})
    if not isinstance(text, str):
        raise ParseError(f"{where(source, line, column)}: a formula must be text, not {type(text).__name__}.")
    if len(text) > MAX_LENGTH:
        raise ParseError(
            f"{where(source, line, column)}: the formula has {len(text)} characters, more than "
            f"contactsym.parse.MAX_LENGTH = {MAX_LENGTH}; split it into named parts, or {_how_to_raise('MAX_LENGTH')}."
        )
    with sp.evaluate(True):
        return _Parser(text, names, source, line, column).parse()
