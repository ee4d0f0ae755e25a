package io.github.jdem846.sun;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.time.ZonedDateTime;
import java.util.Locale;

/**
 * Prints the table of docs/sun.md: how far the sun moves across a square DEM 100 km and 1000 km wide, centred on
 * 0° E at several latitudes, dates and times (UTC = local mean solar time at 0° E). Not a test; run with
 * {@code java -cp target/classes:target/test-classes:<solarpositioning jar> io.github.jdem846.sun.SunSpreadReport}.
 */
public final class SunSpreadReport {

    private static final int SAMPLES = 21; // 21 × 21 suns across the DEM

    private SunSpreadReport() {
    }

    public static void main(String[] args) {
        String[] dates = {"2024-03-20", "2024-06-21", "2024-12-21"};
        int[] hours = {9, 12, 16};
        double[] latitudes = {0, 30, 50, 70};
        System.out.println("| lat | date | UTC | centre az | centre el | 100 km: Δaz | Δel | angle geo | angle TM "
                + "| 1000 km: Δaz | Δel | angle geo | angle TM |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (double lat : latitudes) {
            for (String date : dates) {
                for (int hour : hours) {
                    ZonedDateTime t = ZonedDateTime.parse(date + "T" + String.format("%02d", hour) + ":00Z");
                    SunPosition centre = SolarCalculator.position(t, lat, 0, Observer.SEA_LEVEL);
                    StringBuilder row = new StringBuilder(String.format(Locale.ROOT,
                            "| %.0f° | %s | %02d:00 | %.1f° | %.1f° ", lat, date.substring(5), hour,
                            centre.azimuthDegrees(), centre.elevationDegrees()));
                    for (double km : new double[] {100, 1000}) {
                        GridGeometry g = grid(lat, km);
                        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 1, 1, t,
                                Observer.SEA_LEVEL);
                        row.append(String.format(Locale.ROOT, "| %.2f° | %.2f° | %.2f° | %.2f° ",
                                tiles.azimuthSpreadDegrees(), tiles.elevationSpreadDegrees(),
                                maxAngle(g, tiles, false), maxAngle(g, tiles, true)));
                    }
                    System.out.println(row.append("|"));
                }
            }
        }
        timing();
    }

    /** A geographic grid of SAMPLES² cells, {@code km} wide and high, centred on ({@code lat}, 0). */
    private static GridGeometry grid(double lat, double km) {
        Ellipsoid e = Ellipsoid.WGS84;
        double dLat = km * 1000 / e.meridianArcLength(lat - 0.5, lat + 0.5);
        double dLon = km * 1000 / e.parallelArcLength(lat, 1);
        return new GridGeometry(SAMPLES, SAMPLES, -dLon / 2, lat + dLat / 2, dLon / SAMPLES, dLat / SAMPLES,
                CrsInfo.geographic("WGS 84", 4326, e), PixelAnchor.CORNER);
    }

    /**
     * The largest angle between the light at the grid's centre and at any sample, in degrees, both in the grid's
     * frame: geographic (north-up in every cell), or a transverse Mercator grid on the DEM's central meridian
     * (grid-up turned from true north by the convergence γ = atan(tan Δλ · sin φ)).
     */
    private static double maxAngle(GridGeometry g, SunPerTile tiles, boolean transverseMercator) {
        int mid = SAMPLES / 2;
        LightDirection c = tiles.forTile(mid, mid).toLightDirection();
        double max = 0;
        for (int y = 0; y < SAMPLES; y++) {
            for (int x = 0; x < SAMPLES; x++) {
                SunPosition s = tiles.forTile(x, y);
                double gamma = transverseMercator ? Math.toDegrees(Math.atan(Math.tan(Math.toRadians(g.centerX(x)))
                        * Math.sin(Math.toRadians(g.centerY(y))))) : 0;
                LightDirection l = new LightDirection(s.azimuthDegrees() - gamma, s.elevationDegrees());
                double dot = c.east() * l.east() + c.north() * l.north() + c.up() * l.up();
                max = Math.max(max, Math.toDegrees(Math.acos(Math.min(1, dot))));
            }
        }
        return max;
    }

    private static void timing() {
        ZonedDateTime t = ZonedDateTime.parse("2024-06-21T12:00Z");
        SunAtInstant sun = SunAtInstant.of(t, Observer.SEA_LEVEL);
        double sink = 0;
        for (int round = 0; round < 3; round++) {
            long start = System.nanoTime();
            int n = 200_000;
            for (int i = 0; i < n; i++) {
                sink += sun.position(40 + i * 1e-4, 10).zenithDegrees();
            }
            long place = (System.nanoTime() - start) / n;
            start = System.nanoTime();
            int m = 20_000;
            for (int i = 0; i < m; i++) {
                sink += SolarCalculator.position(t.plusSeconds(i), 40, 10, Observer.SEA_LEVEL).zenithDegrees();
            }
            long full = (System.nanoTime() - start) / m;
            System.out.printf(Locale.ROOT, "round %d: %d ns per place (SunAtInstant), %d ns per full position%n",
                    round, place, full);
        }
        if (sink == 42) {
            System.out.println();
        }
    }
}
