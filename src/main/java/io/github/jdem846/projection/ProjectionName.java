package io.github.jdem846.projection;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The projections known by name ({@code --projection robinson}). Those Apache SIS implements (Mercator, transverse
 * Mercator, equirectangular, Robinson, Mollweide) are computed by SIS; the others by the formula classes of {@link
 * SphericalFormula}. Projections defined for the sphere only (all but Mercator and transverse Mercator) use a
 * sphere of radius a = 6 378 137 m, the WGS 84 semi-major axis, as PROJ and ESRI do for a WGS 84 datum.
 */
public enum ProjectionName {
    /** Plate carrée: x = a λ, y = a φ (PROJ {@code eqc}, ESRI:54001). */
    EQUIRECTANGULAR("equirectangular", "plate-carree", "eqc"),
    /** Mercator on the WGS 84 ellipsoid, true scale on the equator (EPSG:3395 about 0°); cut at ±85.0511°. */
    MERCATOR("mercator", "merc"),
    /** Transverse Mercator on the WGS 84 ellipsoid, scale 1 on the central meridian (the DEM's, by default). */
    TRANSVERSE_MERCATOR("transverse-mercator", "tmerc"),
    /** Robinson (PROJ {@code robin}, ESRI:54030). */
    ROBINSON("robinson", "robin"),
    /** Mollweide (PROJ {@code moll}, ESRI:54009). */
    MOLLWEIDE("mollweide", "moll"),
    /** Winkel Tripel with Winkel's standard parallel arccos(2/π) (PROJ {@code wintri}). */
    WINKEL_TRIPEL("winkel-tripel", "wintri"),
    /** Hammer (Hammer–Aitoff) equal-area (PROJ {@code hammer}). */
    HAMMER("hammer", "hammer-aitoff"),
    /** Aitoff (PROJ {@code aitoff}, ESRI:54043). */
    AITOFF("aitoff"),
    /** Wagner VI (PROJ {@code wag6}). */
    WAGNER_VI("wagner-vi", "wag6");

    private final List<String> names;

    ProjectionName(String... names) {
        this.names = List.of(names);
    }

    /** {@return the name the CLI takes, e.g. {@code winkel-tripel}} */
    public String cliName() {
        return names.get(0);
    }

    /**
     * The projection of a name or alias, case and '_'/'-'/space insensitive ({@code "Winkel Tripel"},
     * {@code wintri}).
     *
     * @param text the name
     * @return the projection, or empty when the name is unknown
     */
    public static Optional<ProjectionName> of(String text) {
        String key = text.strip().toLowerCase(Locale.ROOT).replace('_', '-').replace(' ', '-');
        return Arrays.stream(values()).filter(p -> p.names.contains(key)).findFirst();
    }

    /** {@return the CLI names, comma separated} */
    public static String list() {
        return String.join(", ", Arrays.stream(values()).map(ProjectionName::cliName).toList());
    }
}
