package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/** Exact value and geometry comparisons for reader tests. */
public final class DemAssertions {

    private DemAssertions() {
    }

    /** Same size and the same float32 bits in every cell (NaN = NaN), naming the first differing cell. */
    public static void assertSameValues(Dem expected, Dem actual, String what) {
        assertEquals(expected.width(), actual.width(), what + ": width");
        assertEquals(expected.height(), actual.height(), what + ": height");
        float[] e = expected.backingArray();
        float[] a = actual.backingArray();
        for (int i = 0; i < e.length; i++) {
            boolean same = Float.isNaN(e[i]) ? Float.isNaN(a[i]) : e[i] == a[i];
            if (!same) {
                fail(what + ": cell (col " + i % expected.width() + ", row " + i / expected.width() + ") is " + a[i]
                        + ", expected " + e[i]);
            }
        }
    }

    /** Same size, and origin and cell sizes equal within {@code relTol} relative to their magnitude. */
    static void assertSameGeotransform(GridGeometry expected, GridGeometry actual, double relTol, String what) {
        assertEquals(expected.width(), actual.width(), what + ": width");
        assertEquals(expected.height(), actual.height(), what + ": height");
        assertClose(expected.originX(), actual.originX(), relTol, what + ": originX");
        assertClose(expected.originY(), actual.originY(), relTol, what + ": originY");
        assertClose(expected.cellWidth(), actual.cellWidth(), relTol, what + ": cellWidth");
        assertClose(expected.cellHeight(), actual.cellHeight(), relTol, what + ": cellHeight");
    }

    static void assertClose(double expected, double actual, double relTol, String what) {
        double tol = relTol * Math.max(1e-300, Math.abs(expected));
        if (!(Math.abs(expected - actual) <= tol)) {
            fail(what + ": " + actual + " differs from " + expected + " by more than " + relTol + " relative");
        }
    }

    /** Number of NaN cells. */
    static long noDataCount(Dem dem) {
        long n = 0;
        for (float v : dem.backingArray()) {
            if (Float.isNaN(v)) {
                n++;
            }
        }
        return n;
    }
}
