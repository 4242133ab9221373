"""The top-level parser's mistakes read like every verb's: ``graphkin: <reason>``.

An unknown command once read ``graphkin: graphkin: argument COMMAND: ...``
(the program's name taken for a verb).
"""

from __future__ import annotations

import pytest

from graphkin.cli import main


def _err(argv: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    with pytest.raises(SystemExit) as info:
        main(argv)
    assert info.value.code == 2
    return capsys.readouterr().err


def test_an_unknown_command_is_named_once(capsys: pytest.CaptureFixture[str]) -> None:
    err = _err(["batch"], capsys)
    assert err.startswith("graphkin: argument COMMAND: invalid choice: 'batch'")
    assert "graphkin: graphkin" not in err and err.count("\n") == 1


def test_a_verb_still_names_itself(capsys: pytest.CaptureFixture[str]) -> None:
    err = _err(["sweep"], capsys)
    assert err.startswith("graphkin: sweep: ") and err.count("\n") == 1
