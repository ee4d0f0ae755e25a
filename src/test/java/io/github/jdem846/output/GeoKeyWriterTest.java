package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Expected key lists written out by hand from OGC GeoTIFF 1.1 (key IDs and codes in its Annex). */
class GeoKeyWriterTest {

    private static char[] shorts(int... values) {
        char[] c = new char[values.length];
        for (int i = 0; i < values.length; i++) {
            c[i] = (char) values[i];
        }
        return c;
    }

    @Test
    void projectedWithEpsgCode() {
        GeoKeyWriter keys = GeoKeyWriter.of(CrsInfo.projected("WGS 84 / UTM zone 11N", 32611, 1.0, null));
        assertArrayEquals(shorts(1, 1, 0, 4,
                1024, 0, 1, 1,        // GTModelType = projected
                1025, 0, 1, 1,        // GTRasterType = PixelIsArea
                3072, 0, 1, 32611,    // ProjectedCSType = EPSG:32611
                3076, 0, 1, 9001),    // ProjLinearUnits = metre
                keys.directory());
        assertEquals(0, keys.doubleParams().length);
        assertEquals("", keys.asciiParams());
    }

    @Test
    void geographicWithEpsgCode() {
        GeoKeyWriter keys = GeoKeyWriter.of(CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84));
        assertArrayEquals(shorts(1, 1, 0, 4,
                1024, 0, 1, 2,        // GTModelType = geographic
                1025, 0, 1, 1,
                2048, 0, 1, 4326,     // GeographicType = EPSG:4326
                2054, 0, 1, 9102),    // GeogAngularUnits = degree
                keys.directory());
    }

    @Test
    void unknownCrsHasOnlyTheRasterType() {
        GeoKeyWriter keys = GeoKeyWriter.of(CrsInfo.UNKNOWN);
        assertArrayEquals(shorts(1, 1, 0, 1, 1025, 0, 1, 1), keys.directory());
    }

    @Test
    void userDefinedProjectedKeepsNameAndUnit() {
        GeoKeyWriter feet = GeoKeyWriter.of(CrsInfo.projected("State plane|x", null, 1200.0 / 3937, null));
        assertArrayEquals(shorts(1, 1, 0, 5,
                1024, 0, 1, 1,
                1025, 0, 1, 1,
                1026, 34737, 14, 0,   // GTCitation: "State plane/x|" in GeoAsciiParams at offset 0
                3072, 0, 1, 32767,    // user-defined
                3076, 0, 1, 9003),    // US survey foot
                feet.directory());
        assertEquals("State plane/x|", feet.asciiParams());

        GeoKeyWriter odd = GeoKeyWriter.of(CrsInfo.projected(null, null, 2.5, null));
        assertArrayEquals(shorts(1, 1, 0, 5,
                1024, 0, 1, 1,
                1025, 0, 1, 1,
                3072, 0, 1, 32767,
                3076, 0, 1, 32767,    // user-defined unit ...
                3077, 34736, 1, 0),   // ... of 2.5 m, GeoDoubleParams[0]
                odd.directory());
        assertArrayEquals(new double[]{2.5}, odd.doubleParams());
        assertEquals(9002, GeoKeyWriter.linearUnitCode(0.3048));
    }

    @Test
    void userDefinedGeographicKeepsTheEllipsoid() {
        GeoKeyWriter moon = GeoKeyWriter.of(CrsInfo.geographic("Moon 2000", null, Ellipsoid.MOON));
        assertArrayEquals(shorts(1, 1, 0, 9,
                1024, 0, 1, 2,
                1025, 0, 1, 1,
                2048, 0, 1, 32767,
                2049, 34737, 10, 0,   // GeogCitation "Moon 2000|"
                2050, 0, 1, 32767,
                2054, 0, 1, 9102,
                2056, 0, 1, 32767,
                2057, 34736, 1, 0,    // semi-major axis
                2058, 34736, 1, 1),   // semi-minor axis = semi-major: a sphere
                moon.directory());
        assertArrayEquals(new double[]{1737400, 1737400}, moon.doubleParams());

        GeoKeyWriter grs80 = GeoKeyWriter.of(CrsInfo.geographic(null, null, Ellipsoid.GRS80));
        assertArrayEquals(new double[]{6378137.0, 298.257222101}, grs80.doubleParams());
        char[] d = grs80.directory();
        assertEquals(2059, d[4 + 4 * (d[3] - 1)]); // the last key is the inverse flattening
    }

    @Test
    void keysAreSortedAndCounted() {
        for (CrsInfo crs : List.of(CrsInfo.UNKNOWN, CrsInfo.geographic("x", null, Ellipsoid.MARS),
                CrsInfo.projected("y", null, 0.3048, null), CrsInfo.geographic("WGS 84", 4326, null))) {
            char[] d = GeoKeyWriter.of(crs).directory();
            assertEquals(4 + 4 * d[3], d.length);
            for (int k = 1; k < d[3]; k++) {
                assertTrue(d[4 + 4 * k] > d[4 + 4 * (k - 1)], "keys ascending for " + crs);
            }
        }
    }
}
