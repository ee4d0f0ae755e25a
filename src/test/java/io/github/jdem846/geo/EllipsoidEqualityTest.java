package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;

/** {@link Ellipsoid}'s written-out equals and hashCode keep a record's contract: every component counts. */
class EllipsoidEqualityTest {

    @Test
    void equalComponentsAreEqualWithEqualHashes() {
        Ellipsoid wgs84 = new Ellipsoid("WGS 84", 6378137.0, 298.257223563);
        assertEquals(Ellipsoid.WGS84, wgs84);
        assertEquals(Ellipsoid.WGS84.hashCode(), wgs84.hashCode());
        assertEquals(Ellipsoid.sphere("Moon", 1737400.0), new Ellipsoid("Moon", 1737400.0, 0),
                "an inverse flattening of 0 is the sphere's infinity");
        assertEquals(Ellipsoid.MOON.hashCode(), new Ellipsoid("Moon", 1737400.0, 0).hashCode());
    }

    @Test
    void everyComponentCounts() {
        assertNotEquals(Ellipsoid.WGS84, Ellipsoid.GRS80, "the flattening (same axis)");
        assertNotEquals(Ellipsoid.WGS84, new Ellipsoid("WGS 84", 6378137.5, 298.257223563), "the axis");
        assertNotEquals(Ellipsoid.WGS84, new Ellipsoid("WGS84", 6378137.0, 298.257223563), "the name");
        assertNotEquals(Ellipsoid.WGS84, null);
        assertNotEquals(Ellipsoid.WGS84, (Object) "WGS 84");
    }
}
