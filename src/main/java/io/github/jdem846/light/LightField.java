package io.github.jdem846.light;

/**
 * The light over a grid: one direction for the whole scene, or one that varies with position (the sun recomputed
 * per tile or row from each place's own latitude and longitude).
 */
public interface LightField {

    /** The light at cell ({@code col}, {@code row}). */
    LightDirection at(int col, int row);

    /** The light at the centre of the grid; used where one direction must serve the whole grid. */
    LightDirection central();

    /** True when {@link #at} returns {@link #central()} everywhere. */
    boolean isUniform();

    /** The same light everywhere. */
    static LightField uniform(LightDirection light) {
        java.util.Objects.requireNonNull(light, "light");
        return new LightField() {
            @Override
            public LightDirection at(int col, int row) {
                return light;
            }

            @Override
            public LightDirection central() {
                return light;
            }

            @Override
            public boolean isUniform() {
                return true;
            }
        };
    }
}
