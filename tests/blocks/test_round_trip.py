"""Text -> blocks -> text gives back the program's canonical form, byte for byte."""

from __future__ import annotations

import dataclasses
import inspect
import json
import typing
from pathlib import Path

import pytest

from rootlang import ast, forms
from rootlang.blocks import block_definitions, to_text, to_workspace, toolbox
from rootlang.blocks.definitions import FORMS_BY_BLOCK
from rootlang.checks import parse
from rootlang.formatting import comment_line, format_source

from .programs import random_program

REPO = Path(__file__).resolve().parents[2]
GALLERY = sorted((REPO / "programs").glob("*.root"))


def shape(node: object) -> object:
    """A node without its positions: what `parse(format(t)) == parse(t)` compares."""
    if isinstance(node, ast.Comment):
        return ("comment", comment_line(node), node.own_line)
    if isinstance(node, ast.Node):
        skipped = ("span", "name_span", "else_span", "file")
        names = [f.name for f in dataclasses.fields(node) if f.name not in skipped]
        return (type(node).__name__, *(shape(getattr(node, name)) for name in names))
    if isinstance(node, tuple):
        return tuple(shape(item) for item in node)
    return repr(node)


def round_trip(source: str) -> str:
    workspace = json.loads(json.dumps(to_workspace(source)))  # as it travels to a browser
    return to_text(workspace)


@pytest.mark.parametrize("path", GALLERY, ids=lambda path: path.name)
def test_every_gallery_program_round_trips_to_its_format(path: Path) -> None:
    source = path.read_text(encoding="utf-8")
    canonical = format_source(source)
    assert round_trip(source) == canonical
    assert format_source(canonical) == canonical
    assert shape(parse(canonical)) == shape(parse(source))


@pytest.mark.parametrize("seed", range(250))
def test_random_programs_round_trip(seed: int) -> None:
    """Programs nobody wrote by hand: every form, odd spellings, brackets, comments."""
    source = random_program(seed)
    canonical = format_source(source)
    assert format_source(canonical) == canonical  # idempotent
    assert shape(parse(canonical)) == shape(parse(source))  # same meaning
    assert round_trip(source) == canonical  # lossless


WEIRD = """\
# header
#banner
##### big

to   square size:   # on the header
    # before the loop
    repeat 4 times
        move size
        # at the end of the loop body

        turn right 90 degrees  #after
    # at the end of the procedure


    return
#between
when started
    set x to (1 + 2) * 3 - -4
    set z to round (x + 1) * sqrt 4
    set w to (random 1 to 6) + 2
    IF x = 1:  # first
        print "one", x
    # before else if
    else if x ≥ 2 then
        print "two"

    else   # the else
        say "many"
    play note c#4 for .5 SECONDS
    set s to round x cm
    Forever
        pen down
# end
    # indented end
"""

WEIRD_FORMATTED = """\
# header
# banner
##### big

to square size  # on the header
    # before the loop
    repeat 4
        move size
        # at the end of the loop body

        turn right 90 degrees  # after
    # at the end of the procedure

    return

# between
when started
    set x to (1 + 2) * 3 - -4
    set z to round (x + 1) * sqrt 4
    set w to (random 1 to 6) + 2
    if x = 1  # first
        print "one", x
    # before else if
    else if x >= 2
        print "two"

    else  # the else
        say "many"
    play note C#4 for 0.5 seconds
    set s to round x cm
    repeat forever
        marker down
# end
# indented end
"""


def test_format_keeps_comments_and_blank_lines_where_they_were() -> None:
    assert format_source(WEIRD) == WEIRD_FORMATTED
    assert round_trip(WEIRD) == WEIRD_FORMATTED


def test_comments_lying_on_the_workspace_open_the_program() -> None:
    assert (
        round_trip("# only a plan\n\n#  indented words\n") == "# only a plan\n\n#  indented words\n"
    )
    workspace = to_workspace("when started\n    move 1 cm\n")
    workspace["workspaceComments"] = [{"id": "c", "text": "a note\n\n# another"}]
    assert to_text(workspace) == "# a note\n\n# another\n\nwhen started\n    move 1 cm\n"


def test_comments_go_on_the_block_of_their_line() -> None:
    workspace = to_workspace(WEIRD_FORMATTED)
    procedure = workspace["blocks"]["blocks"][0]
    assert procedure["icons"]["comment"]["text"] == "header\nbanner\n#### big\non the header"
    assert json.loads(procedure["data"]) == {"before": ["cccb"], "eol": [0]}


def test_block_ids_come_from_source_lines() -> None:
    source = "when started\n    move 10 cm\n    turn left 90 degrees\n"
    workspace = to_workspace(source)
    script = workspace["blocks"]["blocks"][0]
    move = script["inputs"]["BODY"]["block"]
    assert (script["id"], move["id"], move["next"]["block"]["id"]) == ("L1", "L2", "L3")
    assert move["inputs"]["DISTANCE"]["shadow"]["id"] == "L2C10E15"


def test_every_node_type_has_a_block() -> None:
    """A node type added to the language without a form or a block fails here."""
    described = {form.node for form in FORMS_BY_BLOCK.values()}
    expressions = set(typing.get_args(ast.AnyExpression))  # value blocks, by their own code
    covered = described | set(forms.SPECIAL_NODES) | expressions
    node_types = {
        member
        for _, member in inspect.getmembers(ast, inspect.isclass)
        if issubclass(member, ast.Node)
        and member not in (ast.Node, ast.Expression, ast.Event, ast.Statement, ast.FormStatement)
    }
    assert node_types - covered == set()
    assert set(forms.SENSORS) == set(ast.SensorKind)


def test_every_form_sets_every_field_of_its_node() -> None:
    """A block builds its node from the form's parts and fixed values, so none may be missing."""
    for form in FORMS_BY_BLOCK.values():
        wanted = {f.name for f in dataclasses.fields(form.node)} - {
            "span",
            "name_span",
            "else_span",
        }
        named = {part.field for part in form.parts if not isinstance(part, forms.Word)}
        assert named | set(form.fixed) == wanted, form.block


def test_block_types_are_unique_and_every_form_has_one() -> None:
    types = [definition["type"] for definition in block_definitions()]
    assert len(types) == len(set(types))
    assert set(FORMS_BY_BLOCK) <= set(types)


def _toolbox_blocks() -> list[dict[str, object]]:
    return [
        item
        for category in toolbox()["contents"]
        for item in category.get("contents", [])
        if item["kind"] == "block"
    ]


@pytest.mark.parametrize("item", _toolbox_blocks(), ids=lambda item: str(item["type"]))
def test_each_block_from_the_toolbox_works_as_it_is(item: dict[str, object]) -> None:
    """Dragged out with its default values, a block reads as a line of a program."""
    block = {key: value for key, value in item.items() if key != "kind"}
    block_type = str(block["type"])
    form = FORMS_BY_BLOCK.get(block_type)
    is_event = form is not None and form in forms.EVENT_FORMS
    if block_type == "root_procedure" or is_event:
        body = {"type": "root_stop_moving"}
        top = {**block, "inputs": {**_inputs(block), "BODY": {"block": body}}}
    elif (form is not None and form.node is ast.SensorRead) or "output" in _definition(block_type):
        say = {"type": "root_say", "inputs": {"TEXT": {"block": block}}}
        top = {"type": "root_when_started", "inputs": {"BODY": {"block": say}}}
    else:
        if block_type in ("root_repeat", "root_forever", "root_repeat_until", "root_while"):
            block["inputs"] = {**_inputs(block),
                               "BODY": {"block": {"type": "root_stop_moving"}}}  # fmt: skip
        if block_type == "controls_if":
            block["inputs"] = {**_inputs(block),
                               "DO0": {"block": {"type": "root_stop_moving"}}}  # fmt: skip
        top = {"type": "root_when_started", "inputs": {"BODY": {"block": block}}}
    text = to_text({"blocks": {"languageVersion": 0, "blocks": [top]}})
    assert parse(text).items  # it reads as a program


def _inputs(block: dict[str, object]) -> dict[str, object]:
    inputs = block.get("inputs", {})
    assert isinstance(inputs, dict)
    return dict(inputs)


def _definition(block_type: str) -> dict[str, object]:
    """Ours; Blockly's own (controls_if) are statements."""
    return next((d for d in block_definitions() if d["type"] == block_type), {})
