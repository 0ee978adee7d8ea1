// Class nomenclatures a scaffolded style recognises, with their published legend colours:
// CORINE Land Cover (level 3 codes), NLCD (the US National Land Cover Database, 2001-2021
// legend) and the Dutch BGT / TOP10NL object types (colours of this project's styles/bgt.json).

/** A class of a nomenclature: its name and legend colour, and an importance weight. */
export interface KnownClass {
  label: string;
  color: string;
  weight?: number;
}

export interface Nomenclature {
  name: string;
  /** Numeric codes apply only when every class value of the data is one of them; names apply one by one. */
  numeric: boolean;
  classes: Record<string, KnownClass>;
}

const CORINE: Nomenclature = {
  name: 'CORINE Land Cover',
  numeric: true,
  classes: {
    111: { label: 'Continuous urban fabric', color: '#e6004d', weight: 2 },
    112: { label: 'Discontinuous urban fabric', color: '#ff0000', weight: 2 },
    121: { label: 'Industrial or commercial units', color: '#cc4df2', weight: 2 },
    122: { label: 'Road and rail networks and associated land', color: '#cc0000', weight: 1.5 },
    123: { label: 'Port areas', color: '#e6cccc' },
    124: { label: 'Airports', color: '#e6cce6' },
    131: { label: 'Mineral extraction sites', color: '#a600cc' },
    132: { label: 'Dump sites', color: '#a64d00' },
    133: { label: 'Construction sites', color: '#ff4dff' },
    141: { label: 'Green urban areas', color: '#ffa6ff' },
    142: { label: 'Sport and leisure facilities', color: '#ffe6ff' },
    211: { label: 'Non-irrigated arable land', color: '#ffffa8' },
    212: { label: 'Permanently irrigated land', color: '#ffff00' },
    213: { label: 'Rice fields', color: '#e6e600' },
    221: { label: 'Vineyards', color: '#e68000' },
    222: { label: 'Fruit trees and berry plantations', color: '#f2a64d' },
    223: { label: 'Olive groves', color: '#e6a600' },
    231: { label: 'Pastures', color: '#e6e64d' },
    241: { label: 'Annual crops associated with permanent crops', color: '#ffe6a6' },
    242: { label: 'Complex cultivation patterns', color: '#ffe64d' },
    243: { label: 'Agriculture with significant areas of natural vegetation', color: '#e6cc4d' },
    244: { label: 'Agro-forestry areas', color: '#f2cca6' },
    311: { label: 'Broad-leaved forest', color: '#80ff00' },
    312: { label: 'Coniferous forest', color: '#00a600' },
    313: { label: 'Mixed forest', color: '#4dff00' },
    321: { label: 'Natural grasslands', color: '#ccf24d' },
    322: { label: 'Moors and heathland', color: '#a6ff80' },
    323: { label: 'Sclerophyllous vegetation', color: '#a6e64d' },
    324: { label: 'Transitional woodland-shrub', color: '#a6f200' },
    331: { label: 'Beaches, dunes, sands', color: '#e6e6e6' },
    332: { label: 'Bare rocks', color: '#cccccc' },
    333: { label: 'Sparsely vegetated areas', color: '#ccffcc' },
    334: { label: 'Burnt areas', color: '#000000' },
    335: { label: 'Glaciers and perpetual snow', color: '#a6e6cc' },
    411: { label: 'Inland marshes', color: '#a6a6ff' },
    412: { label: 'Peat bogs', color: '#4d4dff' },
    421: { label: 'Salt marshes', color: '#ccccff' },
    422: { label: 'Salines', color: '#e6e6ff' },
    423: { label: 'Intertidal flats', color: '#a6a6e6' },
    511: { label: 'Water courses', color: '#00ccf2', weight: 2.5 },
    512: { label: 'Water bodies', color: '#80f2e6', weight: 2.5 },
    521: { label: 'Coastal lagoons', color: '#00ffa6', weight: 2 },
    522: { label: 'Estuaries', color: '#a6ffe6', weight: 2 },
    523: { label: 'Sea and ocean', color: '#e6f2ff', weight: 2 },
  },
};

const NLCD: Nomenclature = {
  name: 'NLCD',
  numeric: true,
  classes: {
    11: { label: 'Open water', color: '#466b9f', weight: 2.5 },
    12: { label: 'Perennial ice/snow', color: '#d1def8', weight: 2 },
    21: { label: 'Developed, open space', color: '#dec5c5', weight: 1.5 },
    22: { label: 'Developed, low intensity', color: '#d99282', weight: 2 },
    23: { label: 'Developed, medium intensity', color: '#eb0000', weight: 2 },
    24: { label: 'Developed, high intensity', color: '#ab0000', weight: 2 },
    31: { label: 'Barren land', color: '#b3ac9f' },
    41: { label: 'Deciduous forest', color: '#68ab5f' },
    42: { label: 'Evergreen forest', color: '#1c5f2c' },
    43: { label: 'Mixed forest', color: '#b5c58f' },
    51: { label: 'Dwarf scrub', color: '#af963c' },
    52: { label: 'Shrub/scrub', color: '#ccb879' },
    71: { label: 'Grassland/herbaceous', color: '#dfdfc2' },
    72: { label: 'Sedge/herbaceous', color: '#d1d182' },
    73: { label: 'Lichens', color: '#a3cc51' },
    74: { label: 'Moss', color: '#82ba9e' },
    81: { label: 'Pasture/hay', color: '#dcd939' },
    82: { label: 'Cultivated crops', color: '#ab6c28' },
    90: { label: 'Woody wetlands', color: '#b8d9eb', weight: 1.5 },
    95: { label: 'Emergent herbaceous wetlands', color: '#6c9fb8', weight: 1.5 },
  },
};

const BGT_TOP10NL: Nomenclature = {
  name: 'BGT/TOP10NL',
  numeric: false,
  classes: {
    pand: { label: 'building', color: '#c98f7e', weight: 4 },
    gebouw: { label: 'building', color: '#c98f7e', weight: 4 },
    overigbouwwerk: { label: 'other structure', color: '#b7a79b', weight: 2 },
    scheiding: { label: 'wall', color: '#7d7470', weight: 1.5 },
    kunstwerkdeel: { label: 'civil engineering work', color: '#8a9096', weight: 2 },
    overbruggingsdeel: { label: 'bridge deck', color: '#9c9c9c', weight: 2 },
    tunneldeel: { label: 'tunnel part', color: '#a8a29a', weight: 2 },
    wegdeel: { label: 'road part', color: '#fbfbf6', weight: 1.5 },
    ondersteunendwegdeel: { label: 'road verge', color: '#d2e3b5', weight: 0.6 },
    spoor: { label: 'railway', color: '#8f8a85', weight: 1.5 },
    spoorbaandeel: { label: 'railway', color: '#8f8a85', weight: 1.5 },
    waterdeel: { label: 'water', color: '#9ec9e8', weight: 2.5 },
    ondersteunendwaterdeel: { label: 'bank', color: '#bcd7a4', weight: 0.6 },
    begroeidterreindeel: { label: 'vegetated terrain', color: '#b3d49a' },
    onbegroeidterreindeel: { label: 'bare terrain', color: '#e9dfc6', weight: 0.8 },
    terrein: { label: 'terrain', color: '#dfe6c8' },
  },
};

export const NOMENCLATURES: readonly Nomenclature[] = [CORINE, NLCD, BGT_TOP10NL];
