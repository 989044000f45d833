# SPDX-License-Identifier: BSD-3-Clause
"""The morphreg.Error hierarchy: the library's classes, each also the Python exception a caller expects."""
import pytest

import morphreg


def test_hierarchy():
    assert issubclass(morphreg.InvalidInputError, morphreg.Error) and issubclass(morphreg.InvalidInputError, ValueError)
    assert issubclass(morphreg.TooFewCorrespondencesError, morphreg.InvalidInputError)
    assert issubclass(morphreg.IoError, morphreg.Error) and issubclass(morphreg.IoError, OSError)
    assert issubclass(morphreg.FormatError, morphreg.IoError)
    assert issubclass(morphreg.NumericalError, morphreg.Error) and issubclass(morphreg.NumericalError, ArithmeticError)
    assert issubclass(morphreg.Error, Exception)


def test_message_is_the_libraries(tmp_path):
    with pytest.raises(OSError) as caught:
        morphreg.load_landmarks(str(tmp_path / "absent.pp"))
    assert isinstance(caught.value, morphreg.IoError)
    assert str(caught.value) == str(tmp_path / "absent.pp") + ": no such file"


def test_bytes_of_a_corrupt_file_in_a_message_are_escaped(tmp_path):
    corrupt = tmp_path / "corrupt.ply"
    corrupt.write_bytes(b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty list uchar int v\x9e\x95s\n"
                        b"end_header\n")
    with pytest.raises(morphreg.FormatError) as caught:
        morphreg.load_cloud(str(corrupt))
    assert "corrupt.ply" in str(caught.value) and "v\\x9e\\x95s" in str(caught.value)
