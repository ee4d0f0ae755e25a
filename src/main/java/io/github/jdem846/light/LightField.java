package io.github.jdem846.light;

/**
 * The light over a grid: one direction for the whole scene, or one that varies with position (the sun recomputed
 * per tile or row from each place's own latitude and longitude).
 */
public interface LightField {

    /**
     * The light at one cell.
     *
     * @param col column of the grid, 0 = west
     * @param row row of the grid, 0 = north
     * @return where the light comes from there
     */
    LightDirection at(int col, int row);

    /** {@return the light at the centre of the grid; used where one direction must serve the whole grid} */
    LightDirection central();

    /** {@return true when {@link #at} returns {@link #central()} everywhere} */
    boolean isUniform();

    /**
     * The same light everywhere.
     *
     * @param light the direction
     * @return the field
     */
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
