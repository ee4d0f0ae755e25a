package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import org.junit.jupiter.api.Test;

class GeoReferenceTest {

    @Test
    void coversTheOuterEdgesOfTheGrid() {
        GridGeometry g = new GridGeometry(10, 4, 500, 900, 2.5, 3, CrsInfo.UNKNOWN, PixelAnchor.CORNER);
        GeoReference geo = GeoReference.of(g);
        assertEquals(new GeoReference(500, 900, 525, 888, CrsInfo.UNKNOWN), geo);
        assertEquals(2.5, geo.pixelWidth(10));
        assertEquals(3, geo.pixelHeight(4));
        assertEquals(12.5, geo.pixelWidth(2)); // a smaller picture keeps the extent
        assertEquals(1.5, geo.pixelHeight(8)); // a larger one too
    }

    @Test
    void rejectsEmptyOrInvertedOrNonFiniteExtents() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new GeoReference(10, 0, 5, 5, CrsInfo.UNKNOWN));
        assertTrue(e.getMessage().contains("east > west"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new GeoReference(0, 5, 5, 5, CrsInfo.UNKNOWN));
        assertThrows(IllegalArgumentException.class, () -> new GeoReference(0, 5, Double.NaN, 0, CrsInfo.UNKNOWN));
        assertThrows(IllegalArgumentException.class,
                () -> new GeoReference(0, Double.POSITIVE_INFINITY, 5, 0, CrsInfo.UNKNOWN));
        assertThrows(IllegalArgumentException.class, () -> new GeoReference(0, 5, 5, 0, CrsInfo.UNKNOWN)
                .pixelWidth(0));
    }
}
