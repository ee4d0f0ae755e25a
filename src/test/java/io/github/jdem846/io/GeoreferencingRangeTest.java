package io.github.jdem846.io;

import io.github.jdem846.testing.TinyTiff;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Georeferencing whose every value is a finite number can still give no usable grid: 1e308 × the rows overflows
 * to an infinite edge, cells of 1e-300 at x = 500000 all have the same x. Each reader refuses it when the file is
 * opened, naming the file and the keys or tags (GridGeometry's own IllegalArgumentException "grid origin must be
 * finite" no longer reaches the caller, and a render no longer fails later without the file's name).
 */
class GeoreferencingRangeTest {

    @TempDir
    Path tmp;

    @FunctionalInterface
    private interface Read {
        Object apply(Path file) throws IOException;
    }

    /** read, inspect and statistics each refuse {@code file} naming {@code named} and the parts. */
    private static void assertRefused(Path file, Path named, String... parts) {
        for (Read read : new Read[] {DemReader::read, DemReader::inspect, DemReader::statistics}) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(file));
            String m = e.getMessage();
            assertTrue(m.startsWith(named + ": "), m);
            for (String part : parts) {
                assertTrue(m.contains(part), "'" + part + "' missing in: " + m);
            }
        }
    }

    private Path gridFloat(String name, String header) throws IOException {
        Path flt = tmp.resolve(name + ".flt");
        Files.write(flt, new byte[3 * 2 * 4]);
        Files.writeString(tmp.resolve(name + ".hdr"), "ncols 3\nnrows 2\n" + header + "byteorder LSBFIRST\n");
        return flt;
    }

    @Test
    void asciiGridWhoseEastEdgeOverflows() throws IOException {
        Path asc = tmp.resolve("v.asc");
        Files.writeString(asc, "ncols 3\nnrows 2\nxllcorner 1756944\nyllcorner 5917124\ncellsize 1e308\n"
                + "1 2 3\n4 5 6\n");
        assertRefused(asc, asc, "header keys 'xllcorner', 'ncols' and 'cellsize': the grid runs from x = 1756944.0"
                + " to Infinity; its edges must be finite numbers");
    }

    @Test
    void gridFloatWhoseNorthEdgeOverflows() throws IOException {
        Path flt = gridFloat("north", "xllcorner 0\nyllcorner 1.7e308\ncellsize 1e307\n");
        assertRefused(flt, tmp.resolve("north.hdr"), "header keys 'yllcorner', 'nrows' and 'cellsize': the grid"
                + " runs from y = 1.7E308 to Infinity");
    }

    @Test
    void gridFloatWithCellsTooSmallForTheirCoordinates() throws IOException {
        Path flt = gridFloat("tiny", "xllcenter 500000\nyllcenter 0\ncellsize 1e-300\n");
        assertRefused(flt, tmp.resolve("tiny.hdr"), "header keys 'xllcenter', 'ncols' and 'cellsize': cells are"
                + " 1.0E-300 wide at x = 500000.0, too small to tell neighbouring cells apart");
    }

    @Test
    void bilWhoseCellsOverflow() throws IOException {
        Path bil = tmp.resolve("b.bil");
        Files.write(bil, new byte[3 * 2 * 2]);
        Files.writeString(tmp.resolve("b.hdr"), "ncols 3\nnrows 2\nnbits 16\nbyteorder I\nulxmap 0\nulymap 0\n"
                + "xdim 1\nydim 1e308\n");
        assertRefused(bil, tmp.resolve("b.hdr"), "header keys 'ulymap', 'nrows' and 'ydim': the grid runs from"
                + " y = -Infinity");
    }

    @Test
    void geoTiffPixelScales() throws IOException {
        Path tiny = TinyTiff.int16(8, 8).georeferenced(500000, 4000000, 1e-300, 1e-300).write(tmp, "s300.tif");
        assertRefused(tiny, tiny, "ModelTiepoint and ModelPixelScale (TIFF tags 33922, 33550): cells are 1.0E-300"
                + " wide at x = 500000.0, too small to tell neighbouring cells apart");
        Path big = TinyTiff.int16(8, 8).georeferenced(500000, 4000000, 1e308, 1e308).write(tmp, "s308.tif");
        assertRefused(big, big, "ModelTiepoint and ModelPixelScale (TIFF tags 33922, 33550): the grid runs from"
                + " x = 500000.0 to Infinity");
        Path inf = TinyTiff.int16(8, 8).georeferenced(0, 0, Double.POSITIVE_INFINITY, 1).write(tmp, "sinf.tif");
        assertRefused(inf, inf, "cells are Infinity wide; the cell size must be a positive finite number");
        Path zero = TinyTiff.int16(8, 8).georeferenced(0, 0, 0, 1).write(tmp, "s0.tif");
        assertRefused(zero, zero, "ModelPixelScale is 0.0, 1.0; both must be positive");
        Path nan = TinyTiff.int16(8, 8).georeferenced(0, 0, 1, Double.NaN).write(tmp, "snan.tif");
        assertRefused(nan, nan, "ModelPixelScale is 1.0, NaN; both must be positive");
        Path tie = TinyTiff.int16(8, 8).georeferenced(1e308, 0, 1e307, 1).write(tmp, "tie.tif");
        assertRefused(tie, tie, "the grid runs from x = 1.0E308 to Infinity");
    }

    @Test
    void geoTiffModelTransformation() throws IOException {
        Path t = TinyTiff.int16(8, 8).doubles(34264, 1e308, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1)
                .write(tmp, "xform.tif");
        assertRefused(t, t, "ModelTransformation (TIFF tag 34264): the grid runs from x = 0.0 to Infinity");
    }

    @Test
    void smallCellsThatCanBeToldApartAreRead() throws IOException {
        // not over-strict: tiny cells near 0 have coordinates of their own, down to the smallest double
        for (double cell : new double[] {1e-300, Double.MIN_VALUE}) {
            Path t = TinyTiff.int16(8, 8).georeferenced(0, 0, cell, cell).write(tmp, "small.tif");
            assertEquals(cell, DemReader.inspect(t).geometry().cellWidth());
            assertEquals(64, DemReader.statistics(t).validCount());
        }
        Path flt = gridFloat("fine", "xllcorner 500000\nyllcorner 0\ncellsize 1e-10\n");
        assertEquals(1e-10, DemReader.read(flt).geometry().cellWidth());
    }
}
